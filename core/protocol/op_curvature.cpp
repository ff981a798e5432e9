// The `curvature` op (geom-protocol-2.md, Analysis): Gaussian, mean and principal curvatures
// of a surface, or the Frenet frame, curvature and torsion of a curve, from exact derivatives.
#include "core/geom/curvature.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"

namespace isoparm::protocol {

namespace {

// A number that may not exist (or overflowed): null.
json optional_number(const std::optional<double>& x) {
    return x && std::isfinite(*x) ? json(*x) : json(nullptr);
}

json surface_entry(const std::optional<geom::SurfaceCurvature>& k) {
    json e = json::object();
    e["gaussian"] = optional_number(k ? std::optional(k->gaussian) : std::nullopt);
    e["mean"] = optional_number(k ? std::optional(k->mean) : std::nullopt);
    e["k1"] = optional_number(k ? std::optional(k->k1) : std::nullopt);
    e["k2"] = optional_number(k ? std::optional(k->k2) : std::nullopt);
    e["d1"] = optional_point(k ? std::optional(k->d1) : std::nullopt);
    e["d2"] = optional_point(k ? std::optional(k->d2) : std::nullopt);
    return e;
}

json curve_entry(const std::optional<geom::CurveCurvature>& k) {
    const geom::CurveCurvature none;
    const geom::CurveCurvature& c = k ? *k : none;
    json e = json::object();
    e["curvature"] = optional_number(c.curvature);
    e["torsion"] = optional_number(c.torsion);
    e["tangent"] = optional_point(c.tangent);
    e["normal"] = optional_point(c.normal);
    e["binormal"] = optional_point(c.binormal);
    return e;
}

} // namespace

OpResult op_curvature(const json& request) {
    if (geom::Status s = check_fields(request, "curvature", {"curve", "surface", "params"}); !s)
        return s.error();
    geom::Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    const json* params = find_member(request, "params");
    if (!params) return missing_member("", "params");
    if (!params->is_array())
        return schema_error(subject->is_surface ? "params is an array of [u, v] pairs"
                                                : "params is an array of numbers",
                            "/params");
    if (static_cast<long long>(params->size()) > geom::max_evaluation_points)
        return geom::make_error(geom::ErrorCode::limit,
                                "too many parameters (" + std::to_string(params->size()) + " > " +
                                    std::to_string(geom::max_evaluation_points) + ")",
                                "/params");
    const double count = static_cast<double>(params->size());
    // Second derivatives for a surface (with the normal), third for a curve's torsion.
    const geom::WorkEstimate cost =
        subject->is_surface ? geom::estimate_surface_evaluation(count, subject->surface.degree_u,
                                                                subject->surface.degree_v, 2, true)
                            : geom::estimate_curve_evaluation(count, subject->curve.degree, 3);
    if (geom::Status ok = geom::spend_work(cost, "/params",
                                           geom::with_thousands(count) + " curvature evaluations");
        !ok)
        return ok.error();

    json curvatures = json::array();
    if (subject->is_surface) {
        auto uv = read_surface_params(*params, subject->surface);
        if (!uv) return uv.error();
        for (const auto& [u, v] : *uv)
            curvatures.push_back(surface_entry(geom::surface_curvature(subject->surface, u, v)));
    } else {
        auto ts = read_curve_params(*params, geom::domain(subject->curve));
        if (!ts) return ts.error();
        for (double t : *ts)
            curvatures.push_back(curve_entry(geom::curve_curvature(subject->curve, t)));
    }
    json answer = json::object();
    answer["curvatures"] = std::move(curvatures);
    return answer;
}

} // namespace isoparm::protocol
