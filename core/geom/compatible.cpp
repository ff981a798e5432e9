// make_compatible: one domain, one degree, one knot vector, shapes unchanged (P&T 10.3, A5.4,
// A5.9).
#include <algorithm>
#include <map>

#include "core/geom/construct.hpp"
#include "core/geom/construct_common.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"

namespace isoparm::geom {

using construct_detail::at_curve;

namespace {

std::string curve_path(size_t k) {
    return "/curves/" + std::to_string(k);
}
std::string curve_name(size_t k) {
    return "curve " + std::to_string(k);
}

// The affine change of parameter t -> (t - a) / (b - a) that maps the domain to [0, 1]: the
// same curve, knots moved. Rounding is monotone, so equal knots stay equal and the order holds;
// the ends map to exactly 0 and 1.
Curve to_unit_domain(const Curve& c) {
    Curve out = c;
    const double a = c.knots[c.degree], b = c.knots[c.count()];
    for (double& t : out.knots) t = (t - a) / (b - a);
    return out;
}

// Joins two pieces that meet at t (each with t at multiplicity p + 1): the curve with t at
// multiplicity p + 1 inside.
Curve join_at(const Curve& first, const Curve& second) {
    const int p = first.degree;
    // first: n1 + p + 1 knots ending in t^(p+1); second starts with t^(p+1): drop those.
    Curve c = first;
    c.knots.insert(c.knots.end(), second.knots.begin() + (p + 1), second.knots.end());
    c.points.insert(c.points.end(), second.points.begin(), second.points.end());
    c.weights.insert(c.weights.end(), second.weights.begin(), second.weights.end());
    if (is_bezier(c.type)) c.type = is_rational(c.type) ? SplineType::nurbs : SplineType::bspline;
    return c;
}

// Degree elevation that also takes interior knots of multiplicity p + 1 (a curve in pieces,
// valid input): A5.9 as implemented in refine.cpp assumes multiplicities <= p, so the curve is
// cut at those knots (a clamped curve's pieces are slices of its knots and points), each piece
// is elevated, and the pieces are joined again.
Expected<Curve> elevate_in_pieces(const Curve& c, int times) {
    const int p = c.degree;
    std::vector<Curve> pieces;
    Curve rest = c;
    for (;;) {
        int f = -1;
        for (const KnotRun& run : knot_runs(rest.knots)) {
            if (run.multiplicity == p + 1 && run.first_index > 0 &&
                run.first_index + p + 1 < static_cast<int>(rest.knots.size())) {
                f = run.first_index;
                break;
            }
        }
        if (f < 0) break;
        Curve first = rest;
        first.knots.assign(rest.knots.begin(), rest.knots.begin() + f + p + 1);
        first.points.assign(rest.points.begin(), rest.points.begin() + f);
        first.weights.assign(rest.weights.begin(), rest.weights.begin() + f);
        rest.knots.erase(rest.knots.begin(), rest.knots.begin() + f);
        rest.points.erase(rest.points.begin(), rest.points.begin() + f);
        rest.weights.erase(rest.weights.begin(), rest.weights.begin() + f);
        pieces.push_back(std::move(first));
    }
    pieces.push_back(std::move(rest));
    Curve joined;
    for (size_t k = 0; k < pieces.size(); ++k) {
        auto r = elevate_degree(pieces[k], times);
        if (!r) return r.error();
        joined = k == 0 ? std::move(r).value() : join_at(joined, *r);
    }
    joined.type = c.type;
    return joined;
}

// The curve with every knot of `merged` raised to its multiplicity there, shape unchanged.
Expected<Curve> refine_to(const Curve& c, const std::map<double, int>& merged) {
    std::vector<double> X;
    for (const auto& [t, m] : merged)
        for (int have = multiplicity(c.knots, t); have < m; ++have) X.push_back(t);
    if (X.empty()) return c;
    const bool rational = is_rational(c.type);
    Knots U = c.knots;
    std::vector<HPoint> Pw = homogeneous_points(c);
    refine_knot_vector(c.degree, U, Pw, X);
    // A zero homogeneous point takes its position from the same refinement of the Cartesian
    // points (curve_from_homogeneous's fallback).
    std::vector<HPoint> fallback;
    if (rational) {
        Knots V = c.knots;
        fallback.resize(c.count());
        for (int i = 0; i < c.count(); ++i) fallback[i] = HPoint(c.points[i], 1.0);
        refine_knot_vector(c.degree, V, fallback, X);
    }
    auto out =
        curve_from_homogeneous(c, c.degree, std::move(U), Pw, rational ? &fallback : nullptr);
    if (out && is_bezier(c.type))
        out->type = rational ? SplineType::nurbs : SplineType::bspline; // spans were added
    return out;
}

} // namespace

Expected<std::vector<Curve>> make_compatible(const std::vector<Curve>& curves) {
    if (curves.size() < 2) {
        return make_error(ErrorCode::schema,
                          "make_compatible needs at least 2 curves, got " +
                              std::to_string(curves.size()),
                          "/curves");
    }
    std::vector<Curve> out;
    out.reserve(curves.size());
    int P = 1;
    for (size_t k = 0; k < curves.size(); ++k) {
        Curve c = to_unit_domain(curves[k]);
        if (!is_clamped(c.knots, c.degree, c.count())) {
            auto r = clamp(c);
            if (!r) return at_curve(r.error(), curve_path(k), curve_name(k));
            c = std::move(r).value();
        }
        if (Status s = validate_knots(c.knots, c.degree, c.count()); !s) {
            return make_error(ErrorCode::knots,
                              curve_name(k) +
                                  ": its knots cannot be mapped to [0, 1] without merging "
                                  "distinct knots (they are too close for double precision)",
                              curve_path(k) + "/knots");
        }
        P = std::max(P, c.degree);
        out.push_back(std::move(c));
    }
    // The merged interior knots (convention 16): after elevation to P every distinct interior
    // knot of a degree-p curve gains P - p copies (A5.9); each keeps its largest multiplicity.
    std::map<double, int> merged;
    for (const Curve& c : out) {
        for (const KnotRun& run : knot_runs(c.knots)) {
            if (!(run.value > 0.0 && run.value < 1.0)) continue;
            int& m = merged[run.value];
            m = std::max(m, run.multiplicity + (P - c.degree));
        }
    }
    long count = P + 1;
    for (const auto& [t, m] : merged) count += m;
    // The caps: a curve's count per direction, and all the curves together as many points as
    // a surface may have (a skin or ruled surface of them would hold exactly that many).
    const long total = count * static_cast<long>(out.size());
    if (count > max_points_per_direction || total > max_points_per_surface) {
        return make_error_nopath(ErrorCode::limit,
                                 "the compatible curves would have " + std::to_string(count) +
                                     " control points each (" + std::to_string(total) +
                                     " in all), above the caps of " +
                                     std::to_string(max_points_per_direction) + " per curve and " +
                                     std::to_string(max_points_per_surface) + " in all");
    }
    for (size_t k = 0; k < out.size(); ++k) {
        Curve& c = out[k];
        if (c.degree < P) {
            auto r = elevate_in_pieces(c, P - c.degree);
            if (!r) return at_curve(r.error(), curve_path(k), curve_name(k));
            c = std::move(r).value();
        }
        auto r = refine_to(c, merged);
        if (!r) return at_curve(r.error(), curve_path(k), curve_name(k));
        c = std::move(r).value();
    }
    return out;
}

} // namespace isoparm::geom
