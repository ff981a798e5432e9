// The rational picture (see the header): denominators, their zero set, the homogeneous lift.
#include "core/geom/rational_picture.hpp"

#include <algorithm>
#include <cmath>

#include "core/geom/basis.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::geom {

namespace {

// Uniform parameters over the domain with every interior knot added (sorted, distinct).
std::vector<double> grid_with_knots(const Surface& s, Dir dir, int cells) {
    const Interval d = domain(s, dir);
    std::vector<double> ts = uniform_params(d.lo, d.hi, std::max(cells, 1) + 1);
    for (const KnotRun& r : knot_runs(s.knots(dir)))
        if (r.value > d.lo && r.value < d.hi) ts.push_back(r.value);
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
    return ts;
}

// The crossing of w = 0 between two points of a cell edge where w has opposite signs
// (positive meaning >= 0): bisection on the exact denominator until the interval stops
// shrinking in floating point.
glm::dvec2 refine_crossing(const Surface& s, glm::dvec2 pos, glm::dvec2 neg) {
    for (int k = 0; k < 200; ++k) {
        const glm::dvec2 mid = 0.5 * (pos + neg);
        if (mid == pos || mid == neg) break;
        if (surface_denominator(s, mid.x, mid.y) >= 0)
            pos = mid;
        else
            neg = mid;
    }
    // The end with the smaller |w|: the nearer of the two to the zero set.
    return std::abs(surface_denominator(s, pos.x, pos.y)) <=
                   std::abs(surface_denominator(s, neg.x, neg.y))
               ? pos
               : neg;
}

} // namespace

double surface_denominator(const Surface& s, double u, double v) {
    if (s.type == SplineType::bezier || s.type == SplineType::bspline) return 1.0;
    const BasisAt bu = basis_at(s.knots_u, s.degree_u, s.n_u, u);
    const BasisAt bv = basis_at(s.knots_v, s.degree_v, s.n_v, v);
    double w = 0;
    for (int a = 0; a <= s.degree_u; ++a) {
        double row = 0;
        for (int b = 0; b <= s.degree_v; ++b)
            row += bv.values[0][static_cast<std::size_t>(b)] *
                   s.weight(bu.first_index + a, bv.first_index + b);
        w += bu.values[0][static_cast<std::size_t>(a)] * row;
    }
    return w;
}

std::vector<ParamSegment> denominator_zero_set(const Surface& s, int resolution) {
    std::vector<ParamSegment> out;
    if (s.type == SplineType::bezier || s.type == SplineType::bspline) return out;
    const std::vector<double> us = grid_with_knots(s, Dir::u, resolution);
    const std::vector<double> vs = grid_with_knots(s, Dir::v, resolution);
    const std::size_t nv = vs.size();
    std::vector<double> w(us.size() * nv);
    for (std::size_t i = 0; i < us.size(); ++i)
        for (std::size_t j = 0; j < nv; ++j) w[i * nv + j] = surface_denominator(s, us[i], vs[j]);
    auto positive = [](double x) { return x >= 0; };
    for (std::size_t i = 0; i + 1 < us.size(); ++i) {
        for (std::size_t j = 0; j + 1 < nv; ++j) {
            // Corners counter-clockwise: (u0,v0), (u1,v0), (u1,v1), (u0,v1).
            const std::array<glm::dvec2, 4> c{
                glm::dvec2{us[i], vs[j]}, glm::dvec2{us[i + 1], vs[j]},
                glm::dvec2{us[i + 1], vs[j + 1]}, glm::dvec2{us[i], vs[j + 1]}};
            const std::array<double, 4> f{w[i * nv + j], w[(i + 1) * nv + j],
                                          w[(i + 1) * nv + j + 1], w[i * nv + j + 1]};
            int mask = 0;
            for (int k = 0; k < 4; ++k) mask |= positive(f[k]) ? 1 << k : 0;
            if (mask == 0 || mask == 15) continue;
            // The crossing on edge k (corner k to corner k + 1).
            auto cross = [&](int k) {
                const int l = (k + 1) % 4;
                return positive(f[k]) ? refine_crossing(s, c[k], c[l])
                                      : refine_crossing(s, c[l], c[k]);
            };
            std::vector<int> edges;
            for (int k = 0; k < 4; ++k)
                if (positive(f[k]) != positive(f[(k + 1) % 4])) edges.push_back(k);
            if (edges.size() == 2) {
                out.push_back({cross(edges[0]), cross(edges[1])});
                continue;
            }
            // A saddle: four crossings. The centre's sign says which corners are joined:
            // when it agrees with corner 0, corner 0's region runs through the middle, so
            // the segments cut off corners 1 and 3.
            const glm::dvec2 mid = 0.5 * (c[0] + c[2]);
            const bool centre = positive(surface_denominator(s, mid.x, mid.y));
            if (centre == positive(f[0])) {
                out.push_back({cross(0), cross(1)}); // around corner 1
                out.push_back({cross(2), cross(3)}); // around corner 3
            } else {
                out.push_back({cross(3), cross(0)}); // around corner 0
                out.push_back({cross(1), cross(2)}); // around corner 2
            }
        }
    }
    return out;
}

std::vector<signed char> denominator_signs(const Surface& s, int resolution) {
    const int r = std::max(resolution, 1);
    std::vector<signed char> out(static_cast<std::size_t>(r) * r);
    const Interval du = domain(s, Dir::u), dv = domain(s, Dir::v);
    for (int i = 0; i < r; ++i) {
        const double u = du.lo + (du.hi - du.lo) * (i + 0.5) / r;
        for (int j = 0; j < r; ++j) {
            const double v = dv.lo + (dv.hi - dv.lo) * (j + 0.5) / r;
            const double w = surface_denominator(s, u, v);
            out[static_cast<std::size_t>(i) * r + j] = w > 0 ? 1 : w < 0 ? -1 : 0;
        }
    }
    return out;
}

std::optional<Curve> isocurve(const Surface& s, Dir fixed, double t) {
    const Dir other = fixed == Dir::u ? Dir::v : Dir::u;
    const int p = s.degree(fixed);
    const BasisAt b = basis_at(s.knots(fixed), p, s.count(fixed), t);
    Curve c;
    c.type = s.type;
    c.degree = s.degree(other);
    c.knots = s.knots(other);
    const int n = s.count(other);
    c.points.resize(static_cast<std::size_t>(n));
    c.weights.resize(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        // Contract homogeneous points (w P, w), never Cartesian ones: that is what makes the
        // result the isocurve of a rational surface.
        glm::dvec3 wp(0.0);
        double w = 0;
        for (int a = 0; a <= p; ++a) {
            const int i = fixed == Dir::u ? b.first_index + a : k;
            const int j = fixed == Dir::u ? k : b.first_index + a;
            const double N = b.values[0][static_cast<std::size_t>(a)];
            wp += N * s.weight(i, j) * s.point(i, j);
            w += N * s.weight(i, j);
        }
        // (w P, 0) with P != 0 is a point at infinity, which Cartesian points and weights
        // cannot hold ((P, 0) stands for the homogeneous origin).
        if (w == 0 && wp != glm::dvec3(0.0)) return std::nullopt;
        c.weights[static_cast<std::size_t>(k)] = w;
        c.points[static_cast<std::size_t>(k)] = w != 0 ? wp / w : glm::dvec3(0.0);
    }
    return c;
}

Curve homogeneous_lift(const Curve& c, std::array<int, 2> axes) {
    Curve h;
    h.type = SplineType::bspline;
    h.degree = c.degree;
    h.knots = c.knots;
    h.points.reserve(c.points.size());
    h.weights.assign(c.points.size(), 1.0);
    const bool rational = c.type == SplineType::rational_bezier || c.type == SplineType::nurbs;
    for (std::size_t k = 0; k < c.points.size(); ++k) {
        const double w = rational ? c.weights[k] : 1.0;
        const glm::dvec3& P = c.points[k];
        h.points.emplace_back(w * P[axes[0]], w * P[axes[1]], w);
    }
    return h;
}

} // namespace isoparm::geom
