// Trims as JSON: loops of 2D curves, read with the curves' own checks and precise paths.
#include "core/json/trim_json.hpp"

#include "core/json/fields.hpp"
#include "core/json/reader.hpp"
#include "core/json/shapes.hpp"

namespace isoparm::json_io {

using geom::Expected;
using nlohmann::json;

namespace {

Expected<geom::TrimLoop> loop_from_json(const json& j, const std::string& path) {
    if (!j.is_array())
        return schema_error("a loop is an array of curves, each ending where the next starts",
                            path);
    geom::TrimLoop loop;
    for (std::size_t k = 0; k < j.size(); ++k) {
        const std::string at = path + geom::pointer_step(static_cast<long>(k));
        const json& c = j[k];
        if (c.is_object())
            if (const auto p = c.find("points"); p != c.end() && p->is_array())
                for (std::size_t i = 0; i < p->size(); ++i)
                    if ((*p)[i].is_array() && (*p)[i].size() != 2)
                        return schema_error("a trim curve's control point is [u, v]",
                                            at + "/points" +
                                                geom::pointer_step(static_cast<long>(i)));
        Expected<geom::Curve> curve = curve_from_json(c);
        if (!curve) return curve.error().under(at);
        loop.curves.push_back(std::move(*curve));
    }
    return loop;
}

json curve_2d_to_json(const geom::Curve& c) {
    json j = curve_to_json(c);
    json pts = json::array();
    for (const glm::dvec3& p : c.points) pts.push_back(json::array({p.x, p.y}));
    j["points"] = std::move(pts);
    return j;
}

} // namespace

Expected<geom::Trim> trim_from_json(const json& j) {
    if (!j.is_object())
        return schema_error("a trim is an object {\"outer\": loop, \"holes\": [loop, ...]}", "");
    if (geom::Status st = check_members(j, "", "a trim", {"outer", "holes"}); !st)
        return st.error();
    geom::Trim t;
    if (const auto it = j.find("outer"); it != j.end()) {
        Expected<geom::TrimLoop> loop = loop_from_json(*it, "/outer");
        if (!loop) return loop.error();
        t.outer = std::move(*loop);
    }
    if (const auto it = j.find("holes"); it != j.end()) {
        if (!it->is_array()) return schema_error("holes is an array of loops", "/holes");
        for (std::size_t k = 0; k < it->size(); ++k) {
            Expected<geom::TrimLoop> loop =
                loop_from_json((*it)[k], "/holes" + geom::pointer_step(static_cast<long>(k)));
            if (!loop) return loop.error();
            t.holes.push_back(std::move(*loop));
        }
    }
    return t;
}

json trim_to_json(const geom::Trim& t) {
    json j = json::object();
    auto loop_json = [](const geom::TrimLoop& loop) {
        json a = json::array();
        for (const geom::Curve& c : loop.curves) a.push_back(curve_2d_to_json(c));
        return a;
    };
    if (t.outer) j["outer"] = loop_json(*t.outer);
    if (!t.holes.empty()) {
        json holes = json::array();
        for (const geom::TrimLoop& h : t.holes) holes.push_back(loop_json(h));
        j["holes"] = std::move(holes);
    }
    return j;
}

Expected<glm::dvec2> read_param(const json& v, const std::string& path) {
    if (!v.is_array() || v.size() != 2 || !is_finite_number(v[0]) || !is_finite_number(v[1]))
        return schema_error("a parameter point is [u, v], two finite numbers", path);
    return glm::dvec2(v[0].get<double>(), v[1].get<double>());
}

} // namespace isoparm::json_io
