// Curves on surfaces: the isocurve's piece where a trim curve runs along u or v, a refined
// least-squares fit elsewhere.
#include "core/geom/trim/curve_on_surface.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/rational_picture.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/trim/fit_samples.hpp"
#include "core/geom/trim/trim.hpp"

namespace isoparm::geom {

namespace {

// Knots mapped linearly from [a, b] onto [lo, hi] (ends exact, equal knots equal).
void rescale(Curve& c, double lo, double hi) {
    const double a = c.knots.front(), b = c.knots.back();
    for (double& k : c.knots) k = k == a ? lo : k == b ? hi : lo + (k - a) / (b - a) * (hi - lo);
}

glm::dvec3 on_surface(const Surface& s, const Curve& uv, double t) {
    const ParamRect d = domain(s);
    const glm::dvec3 q = curve_point(uv, t).value_or(glm::dvec3(0.0));
    return surface_point(s, std::clamp(q.x, d.u.lo, d.u.hi), std::clamp(q.y, d.v.lo, d.v.hi))
        .value_or(glm::dvec3(0.0));
}

// The piece of the isocurve along `along` at the fixed parameter, from a to b (either order).
std::optional<Curve> iso_piece(const Surface& s, Dir fixed, double at, double a, double b) {
    auto iso = isocurve(s, fixed, at);
    if (!iso) return std::nullopt;
    Curve c = std::move(*iso);
    const Interval d = domain(c);
    const double lo = std::clamp(std::min(a, b), d.lo, d.hi),
                 hi = std::clamp(std::max(a, b), d.lo, d.hi);
    if (!(lo < hi)) return std::nullopt;
    if (lo > d.lo) {
        auto r = split(c, lo);
        if (!r) return std::nullopt;
        c = std::move(r->second);
    }
    if (hi < domain(c).hi) {
        auto r = split(c, hi);
        if (!r) return std::nullopt;
        c = std::move(r->first);
    }
    if (auto clamped = clamp(c); clamped) c = std::move(*clamped);
    if (a > b) c = reversed(c);
    return c;
}

} // namespace

Curve curve_on_surface(const Surface& s, const Curve& uv, double tolerance) {
    const Interval d = domain(uv);
    // A straight line of constant u or v: the isocurve's piece, exact.
    if (uv.count() >= 2) {
        const glm::dvec3 a = uv.points.front(), b = uv.points.back();
        bool along_v = true, along_u = true;
        for (const glm::dvec3& p : uv.points) {
            along_v = along_v && p.x == a.x;
            along_u = along_u && p.y == a.y;
        }
        // Monotone along the line (control points in order), so the curve is the segment.
        auto monotone = [&](int axis) {
            for (std::size_t k = 1; k < uv.points.size(); ++k)
                if ((uv.points[k][axis] - uv.points[k - 1][axis]) * (b[axis] - a[axis]) < 0)
                    return false;
            return true;
        };
        // The same speed as the isocurve only when the line is linear in t: degree 1.
        if (uv.degree == 1 && uv.count() == 2 && (along_u || along_v) && !(along_u && along_v) &&
            monotone(along_v ? 1 : 0)) {
            auto piece =
                along_v ? iso_piece(s, Dir::u, a.x, a.y, b.y) : iso_piece(s, Dir::v, a.y, a.x, b.x);
            if (piece) {
                // The isocurve runs with v (or u) itself; the line with t from a to b linearly.
                rescale(*piece, d.lo, d.hi);
                return *piece;
            }
        }
    }
    // Elsewhere a fit that runs with t, its first samples by the curve's and surface's spans.
    const int pieces = static_cast<int>(knot_runs(uv.knots).size() + knot_runs(s.knots_u).size() +
                                        knot_runs(s.knots_v).size());
    return fit_samples([&](double t) { return on_surface(s, uv, t); }, d, pieces, tolerance);
}

} // namespace isoparm::geom
