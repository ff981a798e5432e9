// The `deboor` op: every intermediate point of de Boor's algorithm, for curves and surfaces.
#include "core/geom/deboor.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::Expected;

namespace {

// {"levels": [...], "first_index": s - p}; a level point of homogeneous weight 0 is null.
json triangle_to_json(const geom::DeBoorTriangle& tri) {
    json levels = json::array();
    for (const auto& level : tri.levels) {
        json pts = json::array();
        for (const geom::HPoint& h : level)
            pts.push_back(optional_point(geom::DeBoorTriangle::cartesian(h)));
        levels.push_back(std::move(pts));
    }
    // Members assigned one by one: an initializer list would build a [key, value] pair array
    // per member and destroy it, and nlohmann's destructor allocates (out_of_memory.hpp), so
    // running out of memory there, thousands of times per answer, could not unwind.
    json triangle = json::object();
    triangle["levels"] = std::move(levels);
    triangle["first_index"] = tri.first_index;
    return triangle;
}

Expected<double> parameter(const json& request, std::string_view name, const geom::Interval& dom) {
    Expected<double> t = required_number(request, name);
    if (!t) return t.error();
    if (geom::Status s = check_in_domain(*t, dom, member_path("", name)); !s) return s.error();
    return *t;
}

} // namespace

OpResult op_deboor(const json& request) {
    if (geom::Status s = check_fields(request, "deboor", {"curve", "surface", "param", "u", "v"});
        !s)
        return s.error();
    Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    if (!subject->is_surface) {
        for (const char* name : {"u", "v"}) {
            if (find_member(request, name))
                return schema_error("a curve takes param, not u and v", member_path("", name));
        }
        Expected<double> t = parameter(request, "param", geom::domain(subject->curve));
        if (!t) return t.error();
        return triangle_to_json(geom::deboor_curve(subject->curve, *t));
    }
    if (find_member(request, "param"))
        return schema_error("a surface takes u and v, not param", "/param");
    const geom::Surface& s = subject->surface;
    // Every intermediate point is written: n_v triangles in u and one in v. They count toward
    // the evaluation cap, checked before anything is computed.
    const auto triangle = [](long long p) { return (p + 1) * (p + 2) / 2; };
    const long long points = s.n_v * triangle(s.degree_u) + triangle(s.degree_v);
    if (points > geom::max_evaluation_points) {
        return geom::make_error(geom::ErrorCode::limit,
                                "the de Boor trace would have " + std::to_string(points) +
                                    " intermediate points; at most " +
                                    std::to_string(geom::max_evaluation_points) + " are allowed",
                                "/surface");
    }
    Expected<double> u = parameter(request, "u", geom::domain(s, geom::Dir::u));
    if (!u) return u.error();
    Expected<double> v = parameter(request, "v", geom::domain(s, geom::Dir::v));
    if (!v) return v.error();
    const geom::DeBoorSurfaceTrace trace = geom::deboor_surface(s, *u, *v);
    json u_stage = json::array();
    for (const auto& tri : trace.u_stage) u_stage.push_back(triangle_to_json(tri));
    return json{{"u_stage", std::move(u_stage)},
                {"v_stage", triangle_to_json(trace.v_stage)},
                {"point", optional_point(trace.point())}};
}

} // namespace isoparm::protocol
