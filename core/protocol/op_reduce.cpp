// The reducing ops (geom-protocol-2.md, Fitting and refinement): `remove_knot` (A5.8) and
// `reduce_degree` (A5.11), each within a tolerance in model units. The maths is in
// geom/knot_removal.hpp and geom/degree_reduction.hpp.
#include <algorithm>
#include <limits>

#include "core/geom/degree_reduction.hpp"
#include "core/geom/knot_removal.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

using geom::Expected;

namespace {

constexpr double default_tolerance = 1e-9;

// `tolerance`: a finite number, default 1e-9 (the sign is checked with the geometry).
Expected<double> read_tolerance(const json& request) {
    const json* v = find_member(request, "tolerance");
    if (!v) return default_tolerance;
    return read_finite(*v, "/tolerance", "tolerance");
}

// The common start: fields, subject, direction, then the tolerance.
struct Parsed {
    DirectedSubject subject;
    double tolerance = default_tolerance;
};
Expected<Parsed> parse_common(const json& request, std::string_view op,
                              std::initializer_list<std::string_view> fields) {
    Expected<DirectedSubject> subject = read_directed_subject(request, op, fields);
    if (!subject) return subject.error();
    Expected<double> tolerance = read_tolerance(request);
    if (!tolerance) return tolerance.error();
    return Parsed{std::move(subject).value(), *tolerance};
}

} // namespace

OpResult op_remove_knot(const json& request) {
    Expected<Parsed> parsed = parse_common(
        request, "remove_knot", {"curve", "surface", "direction", "knot", "times", "tolerance"});
    if (!parsed) return parsed.error();
    Expected<double> knot = required_number(request, "knot");
    if (!knot) return knot.error();
    Expected<std::int64_t> times = read_times(request);
    if (!times) return times.error();
    // No knot has more copies than an int holds: more removals than that are as many as there are.
    const int n = static_cast<int>(std::min<std::int64_t>(*times, std::numeric_limits<int>::max()));
    const Subject& sub = parsed->subject.subject;
    const double tol = parsed->tolerance;
    const geom::WorkEstimate cost =
        sub.is_surface ? geom::knot_removal_cost(sub.surface, parsed->subject.dir, *knot, n)
                       : geom::knot_removal_cost(sub.curve, *knot, n);
    if (geom::Status ok = geom::spend_work(cost, subject_path(sub),
                                           "removing the knot " + geom::format_number(*knot));
        !ok)
        return ok.error();
    if (sub.is_surface) {
        auto r = geom::remove_knot(sub.surface, parsed->subject.dir, *knot, n, tol);
        if (!r) return r.error();
        return json{{"surface", surface_to_json(r->surface)},
                    {"removed", r->removed},
                    {"max_deviation", r->max_deviation}};
    }
    auto r = geom::remove_knot(sub.curve, *knot, n, tol);
    if (!r) return r.error();
    return json{{"curve", curve_to_json(r->curve)},
                {"removed", r->removed},
                {"max_deviation", r->max_deviation}};
}

OpResult op_reduce_degree(const json& request) {
    Expected<Parsed> parsed =
        parse_common(request, "reduce_degree", {"curve", "surface", "direction", "tolerance"});
    if (!parsed) return parsed.error();
    const Subject& sub = parsed->subject.subject;
    const geom::WorkEstimate cost =
        sub.is_surface ? geom::degree_reduction_cost(sub.surface, parsed->subject.dir)
                       : geom::degree_reduction_cost(sub.curve);
    if (geom::Status ok = geom::spend_work(cost, subject_path(sub), "reducing the degree"); !ok)
        return ok.error();
    if (sub.is_surface) {
        auto r = geom::reduce_degree(sub.surface, parsed->subject.dir, parsed->tolerance);
        if (!r) return with_weights_path(sub, r.error());
        return json{{"surface", surface_to_json(r->surface)}, {"max_error", r->max_error}};
    }
    auto r = geom::reduce_degree(sub.curve, parsed->tolerance);
    if (!r) return with_weights_path(sub, r.error());
    return json{{"curve", curve_to_json(r->curve)}, {"max_error", r->max_error}};
}

} // namespace isoparm::protocol
