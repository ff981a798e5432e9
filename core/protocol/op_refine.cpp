// The refinement ops (insert_knot, elevate_degree, split): the same refinement, within the same
// limits, as the workstation's commands (geom/refine_within_limits.hpp).
#include <limits>

#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/refine_within_limits.hpp"
#include "core/geom/validate.hpp"
#include "core/json/fields.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::ErrorCode;
using geom::Expected;

namespace {

json shape_to_json(const Subject& subject) {
    return subject.is_surface ? surface_to_json(subject.surface) : curve_to_json(subject.curve);
}

// The refined subject as the answer's one member ("curve" or "surface").
template <class Curve, class Surface>
OpResult refined_answer(const Subject& sub, Curve refine_curve, Surface refine_surface) {
    Subject result = sub;
    if (sub.is_surface) {
        geom::Expected<geom::Surface> s = refine_surface(sub.surface);
        if (!s) return with_weights_path(sub, s.error());
        result.surface = std::move(s).value();
    } else {
        geom::Expected<geom::Curve> c = refine_curve(sub.curve);
        if (!c) return with_weights_path(sub, c.error());
        result.curve = std::move(c).value();
    }
    return json{{sub.is_surface ? "surface" : "curve", shape_to_json(result)}};
}

// Commands take an int; beyond this no degree or size could accept the request anyway.
constexpr std::int64_t times_ceiling = std::int64_t{1} << 24;

} // namespace

OpResult op_insert_knot(const json& request) {
    Expected<DirectedSubject> parsed = read_directed_subject(
        request, "insert_knot", {"curve", "surface", "direction", "knot", "times"});
    if (!parsed) return parsed.error();
    Expected<double> knot = required_number(request, "knot");
    if (!knot) return knot.error();
    Expected<std::int64_t> times = read_times(request);
    if (!times) return times.error();
    const Subject& sub = parsed->subject;
    if (*times > times_ceiling) {
        // Too many for an int, and certainly above any degree: answer as the command would
        // (domain first, then multiplicity) but name the number given.
        const geom::Interval dom =
            sub.is_surface ? geom::domain(sub.surface, parsed->dir) : geom::domain(sub.curve);
        if (geom::Status s = check_in_domain(*knot, dom, "/knot", "knot"); !s) return s.error();
        const int p = sub.is_surface ? sub.surface.degree(parsed->dir) : sub.curve.degree;
        return geom::make_error(
            ErrorCode::multiplicity,
            "inserting " + geom::format_number(*knot) + " " + std::to_string(*times) +
                " time(s) would make its multiplicity exceed the degree " + std::to_string(p),
            "/times");
    }
    const geom::Dir dir = parsed->dir;
    const int n = static_cast<int>(*times);
    return refined_answer(
        sub, [&](const geom::Curve& c) { return geom::insert_knot_within_limits(c, *knot, n); },
        [&](const geom::Surface& s) { return geom::insert_knot_within_limits(s, dir, *knot, n); });
}

OpResult op_elevate_degree(const json& request) {
    if (find_member(request, "triangle")) return op_triangle_elevate(request);
    Expected<DirectedSubject> parsed = read_directed_subject(
        request, "elevate_degree", {"curve", "surface", "direction", "times"});
    if (!parsed) return parsed.error();
    Expected<std::int64_t> times = read_times(request);
    if (!times) return times.error();
    if (*times > times_ceiling) {
        return geom::make_error(ErrorCode::limit,
                                "elevating the degree " + std::to_string(*times) +
                                    " times would need more than " +
                                    std::to_string(geom::max_points_per_direction) +
                                    " control points along the direction",
                                "/times");
    }
    const Subject& sub = parsed->subject;
    const geom::Dir dir = parsed->dir;
    const int n = static_cast<int>(*times);
    return refined_answer(
        sub, [&](const geom::Curve& c) { return geom::elevate_degree_within_limits(c, n); },
        [&](const geom::Surface& s) { return geom::elevate_degree_within_limits(s, dir, n); });
}

OpResult op_split(const json& request) {
    if (find_member(request, "triangle")) return op_triangle_split(request);
    Expected<DirectedSubject> parsed =
        read_directed_subject(request, "split", {"curve", "surface", "direction", "param"});
    if (!parsed) return parsed.error();
    Expected<double> t = required_number(request, "param");
    if (!t) return t.error();
    const Subject& sub = parsed->subject;
    json pieces;
    if (sub.is_surface) {
        auto split = geom::split(sub.surface, parsed->dir, *t);
        if (!split) return split.error();
        pieces = json::array({surface_to_json(split->first), surface_to_json(split->second)});
    } else {
        auto split = geom::split(sub.curve, *t);
        if (!split) return split.error();
        pieces = json::array({curve_to_json(split->first), curve_to_json(split->second)});
    }
    return json{{"pieces", std::move(pieces)}};
}

} // namespace isoparm::protocol
