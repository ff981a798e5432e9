// Triangular Bezier patches in the protocol (geom-protocol-2.md, Blossoms and triangular
// patches): `evaluate`, `de_casteljau`, `elevate_degree` and `split` given a `triangle`.
#include <cmath>

#include "core/geom/triangle.hpp"
#include "core/geom/validate.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::Expected;

namespace {

// How far r + s + t may be from 1 (the spec's rule).
constexpr double barycentric_tolerance = 1e-12;

Expected<geom::TrianglePatch> read_triangle(const json& request) {
    const json* t = find_member(request, "triangle");
    if (!t) return missing_member("", "triangle");
    Expected<geom::TrianglePatch> patch = triangle_from_json(*t);
    if (!patch) return patch.error().under("/triangle");
    return patch;
}

// [r, s, t]: numbers, each >= 0, summing to 1 within 1e-12 (`domain` otherwise); `strict`
// (split) also wants each > 0.
Expected<geom::Barycentric> read_barycentric(const json& v, const std::string& path, bool strict) {
    Expected<geom::Barycentric> read = triangle_param_from_json(v, path);
    if (!read) return read.error();
    const geom::Barycentric p = *read;
    const double sum = p[0] + p[1] + p[2];
    const bool inside =
        strict ? p[0] > 0 && p[1] > 0 && p[2] > 0 : p[0] >= 0 && p[1] >= 0 && p[2] >= 0;
    if (!inside || !(std::abs(sum - 1) <= barycentric_tolerance))
        return geom::make_error(
            geom::ErrorCode::domain,
            "[" + geom::format_number(p[0]) + ", " + geom::format_number(p[1]) + ", " +
                geom::format_number(p[2]) + "] is not " + (strict ? "strictly inside" : "in") +
                " the triangle (each coordinate " + (strict ? "> 0" : ">= 0") + ", sum 1)",
            path);
    return p;
}

// de Casteljau's cost (work_budget.hpp) charged before anything is computed.
geom::Status spend_on_triangle(const geom::TrianglePatch& t, double count, int d, bool all_levels,
                               const std::string& path) {
    return geom::spend_work(
        geom::estimate_triangle_de_casteljau(count, t.degree, d, all_levels), path,
        geom::with_thousands(count) + " de Casteljau constructions on a degree-" +
            std::to_string(t.degree) + " triangle");
}

// The fields of de_casteljau and split: a triangle and one `param`, with de Casteljau's cost
// charged (`strict`: strictly inside; `all_levels`: the answer holds every level).
struct TriangleAt {
    geom::TrianglePatch triangle;
    geom::Barycentric param{};
};
Expected<TriangleAt> read_triangle_at(const json& request, std::string_view op, bool strict,
                                      bool all_levels) {
    if (geom::Status s = check_fields(request, op, {"triangle", "param"}); !s) return s.error();
    Expected<geom::TrianglePatch> t = read_triangle(request);
    if (!t) return t.error();
    const json* param = find_member(request, "param");
    if (!param) return missing_member("", "param");
    Expected<geom::Barycentric> p = read_barycentric(*param, "/param", strict);
    if (!p) return p.error();
    if (geom::Status ok = spend_on_triangle(*t, 1, 0, all_levels, "/triangle"); !ok)
        return ok.error();
    return TriangleAt{std::move(t).value(), *p};
}

json optional_points(const std::vector<std::optional<glm::dvec3>>& level) {
    json out = json::array();
    for (const auto& p : level) out.push_back(optional_point(p));
    return out;
}

} // namespace

OpResult op_triangle_evaluate(const json& request) {
    if (geom::Status s = check_fields(request, "evaluate", {"triangle", "params", "derivatives"});
        !s)
        return s.error();
    Expected<geom::TrianglePatch> t = read_triangle(request);
    if (!t) return t.error();
    Expected<std::int64_t> d = integer_option(request, "derivatives", 0, 0, 2,
                                              "derivatives is an integer 0..2 for a triangle");
    if (!d) return d.error();
    const json* params = find_member(request, "params");
    if (!params) return missing_member("", "params");
    if (!params->is_array()) return schema_error("params is an array of [r, s, t]", "/params");
    if (static_cast<long long>(params->size()) > geom::max_evaluation_points)
        return geom::make_error(geom::ErrorCode::limit,
                                "too many parameters (" + std::to_string(params->size()) + ")",
                                "/params");
    const double count = static_cast<double>(params->size());
    if (geom::Status ok = spend_on_triangle(*t, count, static_cast<int>(*d), false, "/params"); !ok)
        return ok.error();
    json points = json::array(), derivatives = json::array();
    for (std::size_t k = 0; k < params->size(); ++k) {
        Expected<geom::Barycentric> p =
            read_barycentric((*params)[k], "/params/" + std::to_string(k), false);
        if (!p) return p.error();
        if (*d == 0) {
            points.push_back(optional_point(geom::triangle_point(*t, *p)));
            continue;
        }
        const auto D = geom::triangle_derivatives(*t, *p, static_cast<int>(*d));
        points.push_back(D ? point_to_json((*D)[0][0]) : json(nullptr));
        if (!D) {
            derivatives.push_back(nullptr);
            continue;
        }
        json table = json::array();
        for (int a = 0; a <= *d; ++a) {
            json row = json::array();
            for (int b = 0; b <= *d; ++b)
                row.push_back(a + b <= *d ? point_to_json((*D)[a][b]) : json(nullptr));
            table.push_back(std::move(row));
        }
        derivatives.push_back(std::move(table));
    }
    json answer = json::object();
    answer["points"] = std::move(points);
    if (*d > 0) answer["derivatives"] = std::move(derivatives);
    return answer;
}

OpResult op_de_casteljau(const json& request) {
    Expected<TriangleAt> at = read_triangle_at(request, "de_casteljau", false, true);
    if (!at) return at.error();
    json levels = json::array();
    for (const auto& level : geom::triangle_de_casteljau(at->triangle, at->param))
        levels.push_back(optional_points(level));
    json answer = json::object();
    answer["levels"] = std::move(levels);
    return answer;
}

OpResult op_triangle_elevate(const json& request) {
    if (geom::Status s = check_fields(request, "elevate_degree", {"triangle", "times"}); !s)
        return s.error();
    Expected<geom::TrianglePatch> t = read_triangle(request);
    if (!t) return t.error();
    Expected<std::int64_t> times =
        integer_option(request, "times", 1, 1, std::numeric_limits<std::int64_t>::max(),
                       "times is an integer >= 1");
    if (!times) return times.error();
    // Compared without adding: times may be near the largest integer (1e19 reads as that), and
    // degree + times would wrap around to a negative degree.
    if (*times > geom::max_triangle_degree - t->degree)
        return geom::make_error(geom::ErrorCode::limit,
                                "elevating degree " + std::to_string(t->degree) + " " +
                                    std::to_string(*times) + " times passes the cap of " +
                                    std::to_string(geom::max_triangle_degree),
                                "/times");
    json answer = json::object();
    answer["triangle"] = triangle_to_json(geom::elevate_triangle(*t, static_cast<int>(*times)));
    return answer;
}

OpResult op_triangle_split(const json& request) {
    Expected<TriangleAt> at = read_triangle_at(request, "split", true, false);
    if (!at) return at.error();
    auto pieces = geom::split_triangle(at->triangle, at->param);
    if (!pieces) return pieces.error();
    json list = json::array();
    for (const geom::TrianglePatch& piece : *pieces) list.push_back(triangle_to_json(piece));
    json answer = json::object();
    answer["pieces"] = std::move(list);
    return answer;
}

} // namespace isoparm::protocol
