// The `evaluate` op: points, derivatives up to order 3 and unit normals at given parameters.
#include <cmath>

#include "core/doc/json_geom.hpp"
#include "core/doc/protocol_detail.hpp"
#include "core/doc/work_budget.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/validate.hpp"

namespace isoparm::doc::protocol {

using geom::Expected;

namespace {

std::string param_path(std::size_t i) {
    return "/params/" + std::to_string(i);
}

// The curve's parameters, each a finite number in the domain.
Expected<std::vector<double>> curve_params(const json& params, const geom::Interval& dom) {
    std::vector<double> ts;
    ts.reserve(params.size());
    for (std::size_t i = 0; i < params.size(); ++i) {
        const std::string path = param_path(i);
        if (params[i].is_array()) return schema_error("a curve parameter is a number t", path);
        Expected<double> t = read_number(params[i], path, "a curve parameter");
        if (!t) return t.error();
        if (geom::Status s = check_in_domain(*t, dom, path); !s) return s.error();
        ts.push_back(*t);
    }
    return ts;
}

// The surface's parameters, each [u, v] with u and v in their domains.
Expected<std::vector<std::array<double, 2>>> surface_params(const json& params,
                                                            const geom::Surface& s) {
    const geom::Interval dom[2] = {surface_domain(s, geom::Dir::u),
                                   surface_domain(s, geom::Dir::v)};
    std::vector<std::array<double, 2>> uv;
    uv.reserve(params.size());
    for (std::size_t i = 0; i < params.size(); ++i) {
        const std::string path = param_path(i);
        if (!params[i].is_array() || params[i].size() != 2)
            return schema_error("a surface parameter is [u, v]", path);
        std::array<double, 2> x{};
        for (int k = 0; k < 2; ++k) {
            const std::string sub = path + "/" + std::to_string(k);
            Expected<double> t =
                read_number(params[i][static_cast<std::size_t>(k)], sub, k == 0 ? "u" : "v");
            if (!t) return t.error();
            if (geom::Status st = check_in_domain(*t, dom[k], sub, k == 0 ? "u" : "v"); !st)
                return st.error();
            x[static_cast<std::size_t>(k)] = *t;
        }
        uv.push_back(x);
    }
    return uv;
}

json curve_results(const geom::Curve& c, const std::vector<double>& ts, int d) {
    json points = json::array();
    json ders = json::array();
    for (double t : ts) {
        auto C = geom::curve_derivatives(c, t, d);
        points.push_back(C ? point_to_json((*C)[0]) : json(nullptr));
        if (d >= 1) {
            if (!C) {
                ders.push_back(nullptr);
                continue;
            }
            json entry = json::array();
            bool finite = true;
            for (int k = 0; k <= d; ++k) {
                entry.push_back(point_to_json((*C)[static_cast<std::size_t>(k)]));
                finite = finite && !entry.back().is_null();
            }
            ders.push_back(finite ? std::move(entry) : json(nullptr));
        }
    }
    json out = {{"points", std::move(points)}};
    if (d >= 1) out["derivatives"] = std::move(ders);
    return out;
}

json surface_results(const geom::Surface& s, const std::vector<std::array<double, 2>>& uv, int d,
                     bool normals) {
    json points = json::array();
    json ders = json::array();
    json norms = json::array();
    // Normals need first derivatives even when fewer were asked for.
    const int order = normals ? std::max(d, 1) : d;
    for (const auto& [u, v] : uv) {
        auto D = geom::surface_derivatives(s, u, v, order);
        points.push_back(D ? point_to_json(D->D[0][0]) : json(nullptr));
        if (d >= 1) {
            if (!D) {
                ders.push_back(nullptr);
            } else {
                // D[a][b] = d^(a+b) S / du^a dv^b, null where a + b > d.
                json table = json::array();
                bool finite = true;
                for (int a = 0; a <= d; ++a) {
                    json row = json::array();
                    for (int b = 0; b <= d; ++b) {
                        row.push_back(a + b <= d ? point_to_json(D->D[a][b]) : json(nullptr));
                        finite = finite && (a + b > d || !row.back().is_null());
                    }
                    table.push_back(std::move(row));
                }
                // An entry beyond the range of doubles is null as a whole, like a missing point.
                ders.push_back(finite ? std::move(table) : json(nullptr));
            }
        }
        if (normals) {
            std::optional<glm::dvec3> n;
            if (D) n = geom::normal_from_derivatives(*D);
            norms.push_back(optional_point(n));
        }
    }
    json out = {{"points", std::move(points)}};
    if (d >= 1) out["derivatives"] = std::move(ders);
    if (normals) out["normals"] = std::move(norms);
    return out;
}

} // namespace

OpResult op_evaluate(const json& request) {
    if (geom::Status s = check_fields(request, "evaluate",
                                      {"curve", "surface", "params", "derivatives", "normals"});
        !s)
        return s.error();
    Expected<Subject> subject = read_subject(request, true, true);
    if (!subject) return subject.error();
    Expected<std::int64_t> d = integer_option(
        request, "derivatives", 0, 0, geom::max_derivative_order, "derivatives is an integer 0..3");
    if (!d) return d.error();
    bool normals = false;
    if (const json* n = find_field(request, "normals")) {
        if (!subject->is_surface) return schema_error("normals are for surfaces", "/normals");
        if (!n->is_boolean()) return schema_error("normals is true or false", "/normals");
        normals = n->get<bool>();
    }
    const json* params = find_field(request, "params");
    if (!params) return missing_field("params");
    if (!params->is_array()) {
        return schema_error(subject->is_surface ? "params is an array of [u, v] pairs"
                                                : "params is an array of numbers",
                            "/params");
    }
    if (static_cast<long long>(params->size()) > geom::max_evaluation_points) {
        return geom::make_error(geom::ErrorCode::limit,
                                "too many parameters (" + std::to_string(params->size()) + " > " +
                                    std::to_string(geom::max_evaluation_points) + ")",
                                "/params");
    }
    const int order = static_cast<int>(*d);
    // The work budget before any parameter is read (work_budget.hpp).
    const double count = static_cast<double>(params->size());
    if (subject->is_surface) {
        const geom::Surface& s = subject->surface;
        const WorkEstimate cost =
            estimate_surface_evaluation(count, s.degree_u, s.degree_v, order, normals);
        if (geom::Status ok = spend_work(
                cost, "/params",
                with_thousands(count) + " parameters of a degree (" + std::to_string(s.degree_u) +
                    ", " + std::to_string(s.degree_v) + ") surface" +
                    (order > 0 ? " with derivatives up to " + std::to_string(order)
                               : std::string{}) +
                    (normals ? " and normals" : ""));
            !ok)
            return ok.error();
    } else {
        const WorkEstimate cost = estimate_curve_evaluation(count, subject->curve.degree, order);
        if (geom::Status ok =
                spend_work(cost, "/params",
                           with_thousands(count) + " parameters of a degree-" +
                               std::to_string(subject->curve.degree) + " curve" +
                               (order > 0 ? " with derivatives up to " + std::to_string(order)
                                          : std::string{}));
            !ok)
            return ok.error();
    }
    if (subject->is_surface) {
        auto uv = surface_params(*params, subject->surface);
        if (!uv) return uv.error();
        return surface_results(subject->surface, *uv, order, normals);
    }
    auto ts = curve_params(*params, curve_domain(subject->curve));
    if (!ts) return ts.error();
    return curve_results(subject->curve, *ts, order);
}

} // namespace isoparm::doc::protocol
