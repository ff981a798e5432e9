// The `evaluate` op: points, derivatives up to order 3 and unit normals at given parameters.
#include <cmath>
#include <memory>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "core/geom/work_budget.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/detail.hpp"
#include "core/protocol/stream.hpp"

namespace isoparm::protocol {

using geom::Expected;

namespace {

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

// A checked `evaluate` request: what to evaluate, where, to which order.
struct EvaluateRequest {
    Subject subject;
    int order = 0;
    bool normals = false;
    std::vector<double> ts;                // a curve's parameters
    std::vector<std::array<double, 2>> uv; // a surface's parameters
};

Expected<EvaluateRequest> read_evaluate(const json& request) {
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
    if (const json* n = find_member(request, "normals")) {
        if (!subject->is_surface) return schema_error("normals are for surfaces", "/normals");
        if (!n->is_boolean()) return schema_error("normals is true or false", "/normals");
        normals = n->get<bool>();
    }
    const json* params = find_member(request, "params");
    if (!params) return missing_member("", "params");
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
        const geom::WorkEstimate cost =
            geom::estimate_surface_evaluation(count, s.degree_u, s.degree_v, order, normals);
        if (geom::Status ok = geom::spend_work(
                cost, "/params",
                geom::with_thousands(count) + " parameters of a degree (" + std::to_string(s.degree_u) +
                    ", " + std::to_string(s.degree_v) + ") surface" +
                    (order > 0 ? " with derivatives up to " + std::to_string(order)
                               : std::string{}) +
                    (normals ? " and normals" : ""));
            !ok)
            return ok.error();
    } else {
        const geom::WorkEstimate cost = geom::estimate_curve_evaluation(count, subject->curve.degree, order);
        if (geom::Status ok =
                geom::spend_work(cost, "/params",
                           geom::with_thousands(count) + " parameters of a degree-" +
                               std::to_string(subject->curve.degree) + " curve" +
                               (order > 0 ? " with derivatives up to " + std::to_string(order)
                                          : std::string{}));
            !ok)
            return ok.error();
    }
    EvaluateRequest e;
    e.order = order;
    e.normals = normals;
    if (subject->is_surface) {
        auto uv = read_surface_params(*params, subject->surface);
        if (!uv) return uv.error();
        e.uv = std::move(uv).value();
    } else {
        auto ts = read_curve_params(*params, geom::domain(subject->curve));
        if (!ts) return ts.error();
        e.ts = std::move(ts).value();
    }
    e.subject = std::move(subject).value();
    return e;
}

// The values of an evaluation, computed before any text is written: per parameter a fixed
// number of points (curve: C..C^(d); surface: point, the (d+1) x (d+1) table when d >= 1, the
// normal) and whether each exists.
struct Evaluated {
    std::size_t stride = 0;
    std::vector<glm::dvec3> values;
    std::vector<std::uint8_t> exists;        // the point (and derivatives) exist
    std::vector<std::uint8_t> normal_exists; // surfaces with normals
};

Evaluated evaluate_compact(const EvaluateRequest& e) {
    Evaluated r;
    const int d = e.order;
    if (!e.subject.is_surface) {
        r.stride = static_cast<std::size_t>(d + 1);
        r.values.resize(e.ts.size() * r.stride);
        r.exists.resize(e.ts.size());
        for (std::size_t i = 0; i < e.ts.size(); ++i) {
            auto C = geom::curve_derivatives(e.subject.curve, e.ts[i], d);
            r.exists[i] = C.has_value();
            if (C)
                for (int k = 0; k <= d; ++k)
                    r.values[i * r.stride + static_cast<std::size_t>(k)] =
                        (*C)[static_cast<std::size_t>(k)];
        }
        return r;
    }
    const std::size_t table = d >= 1 ? static_cast<std::size_t>((d + 1) * (d + 1)) : 0;
    r.stride = 1 + table + (e.normals ? 1 : 0);
    r.values.resize(e.uv.size() * r.stride);
    r.exists.resize(e.uv.size());
    if (e.normals) r.normal_exists.resize(e.uv.size());
    const int order = e.normals ? std::max(d, 1) : d;
    for (std::size_t i = 0; i < e.uv.size(); ++i) {
        auto D = geom::surface_derivatives(e.subject.surface, e.uv[i][0], e.uv[i][1], order);
        r.exists[i] = D.has_value();
        if (!D) continue;
        glm::dvec3* out = &r.values[i * r.stride];
        out[0] = D->D[0][0];
        if (d >= 1)
            for (int a = 0; a <= d; ++a)
                for (int b = 0; b <= d; ++b)
                    out[1 + static_cast<std::size_t>(a * (d + 1) + b)] = D->D[a][b];
        if (e.normals) {
            const std::optional<glm::dvec3> n = geom::normal_from_derivatives(*D);
            r.normal_exists[i] = n.has_value();
            if (n) out[r.stride - 1] = *n;
        }
    }
    return r;
}

// Writes the answer exactly as write_json writes curve_results / surface_results: members
// ok, points, derivatives, normals; an entry of derivatives is null as a whole where the
// point does not exist or one of its values is not finite.
void write_evaluated(const EvaluateRequest& e, const Evaluated& r, std::string& buffer,
                     std::ostream& out) {
    const int d = e.order;
    const std::size_t count = r.exists.size();
    buffer += "{\"ok\": true, \"points\": [";
    for (std::size_t i = 0; i < count; ++i) {
        if (i > 0) buffer += ", ";
        append_point(buffer, r.values[i * r.stride], r.exists[i] != 0);
        flush_if_full(buffer, out);
    }
    buffer += ']';
    if (d >= 1) {
        buffer += ", \"derivatives\": [";
        for (std::size_t i = 0; i < count; ++i) {
            if (i > 0) buffer += ", ";
            const glm::dvec3* v = &r.values[i * r.stride];
            if (!e.subject.is_surface) {
                bool finite = r.exists[i] != 0;
                for (int k = 0; k <= d && finite; ++k) finite = writable_point(v[k]);
                if (!finite) {
                    buffer += "null";
                } else {
                    buffer += '[';
                    for (int k = 0; k <= d; ++k) {
                        if (k > 0) buffer += ", ";
                        append_point(buffer, v[k]);
                    }
                    buffer += ']';
                }
            } else {
                const glm::dvec3* t = v + 1; // the table, row-major
                bool finite = r.exists[i] != 0;
                for (int a = 0; a <= d && finite; ++a)
                    for (int b = 0; b + a <= d && finite; ++b)
                        finite = writable_point(t[a * (d + 1) + b]);
                if (!finite) {
                    buffer += "null";
                } else {
                    buffer += '[';
                    for (int a = 0; a <= d; ++a) {
                        if (a > 0) buffer += ", ";
                        buffer += '[';
                        for (int b = 0; b <= d; ++b) {
                            if (b > 0) buffer += ", ";
                            if (a + b <= d)
                                append_point(buffer, t[a * (d + 1) + b]);
                            else
                                buffer += "null";
                        }
                        buffer += ']';
                    }
                    buffer += ']';
                }
            }
            flush_if_full(buffer, out);
        }
        buffer += ']';
    }
    if (e.normals) {
        buffer += ", \"normals\": [";
        for (std::size_t i = 0; i < count; ++i) {
            if (i > 0) buffer += ", ";
            append_point(buffer, r.values[i * r.stride + r.stride - 1], r.normal_exists[i] != 0);
            flush_if_full(buffer, out);
        }
        buffer += ']';
    }
    buffer += '}';
}

} // namespace

OpResult op_evaluate(const json& request) {
    if (find_member(request, "triangle")) return op_triangle_evaluate(request);
    Expected<EvaluateRequest> e = read_evaluate(request);
    if (!e) return e.error();
    if (e->subject.is_surface)
        return surface_results(e->subject.surface, e->uv, e->order, e->normals);
    return curve_results(e->subject.curve, e->ts, e->order);
}

Expected<StreamedAnswer> streamed_evaluate(const json& request) {
    Expected<EvaluateRequest> e = read_evaluate(request);
    if (!e) return e.error();
    auto request_kept = std::make_shared<const EvaluateRequest>(std::move(e).value());
    auto values = std::make_shared<const Evaluated>(evaluate_compact(*request_kept));
    return StreamedAnswer([request_kept, values](std::string& buffer, std::ostream& out) {
        write_evaluated(*request_kept, *values, buffer, out);
    });
}

} // namespace isoparm::protocol
