// Evaluation: derivatives against finite differences, rational cases, weights 0 and < 0,
// endpoint interpolation, normals at degenerate points.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {
void expect_near(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}
} // namespace

TEST(Evaluate, ClampedCurveInterpolatesEndPoints) {
    RandomGeometry g(1);
    for (int trial = 0; trial < 50; ++trial) {
        const Curve c = g.curve(g.integer(1, 9), 12, trial % 2);
        const Interval d = domain(c);
        expect_near(*curve_point(c, d.lo), c.points.front(), 1e-12);
        expect_near(*curve_point(c, d.hi), c.points.back(), 1e-12);
    }
}

TEST(Evaluate, QuarterCircleIsExact) {
    Curve c;
    c.type = SplineType::rational_bezier;
    c.degree = 2;
    c.knots = bezier_knots(2);
    c.points = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    c.weights = {1, std::sqrt(0.5), 1};
    for (double t = 0; t <= 1.0; t += 0.125) {
        const auto d = *curve_derivatives(c, t, 2);
        EXPECT_NEAR(glm::length(d[0]), 1.0, 1e-15);
        EXPECT_NEAR(glm::dot(d[0], d[1]), 0.0, 1e-13); // tangent is perpendicular to radius
    }
}

TEST(Evaluate, CurveDerivativesMatchFiniteDifferences) {
    RandomGeometry g(5);
    for (int trial = 0; trial < 80; ++trial) {
        const Curve c = g.curve(g.integer(1, 5), g.integer(6, 10), trial % 2 == 0, trial % 3 != 0);
        const Interval dom = domain(c);
        const double t = g.uniform(dom.lo, dom.hi), h = 1e-5;
        bool near_knot = t - 2 * h < dom.lo || t + 2 * h > dom.hi;
        for (double k : c.knots) near_knot |= std::abs(k - t) < 3 * h;
        if (near_knot) continue;
        const auto D = *curve_derivatives(c, t, 3);
        const auto Dp = *curve_derivatives(c, t + h, 2), Dm = *curve_derivatives(c, t - h, 2);
        for (int k = 0; k < 2; ++k) {
            const glm::dvec3 fd = (Dp[k] - Dm[k]) / (2 * h);
            const double scale = 1 + glm::length(D[k + 1]);
            EXPECT_NEAR(glm::length(fd - D[k + 1]) / scale, 0.0, 1e-5) << "order " << k + 1;
        }
    }
}

TEST(Evaluate, SurfaceDerivativesMatchFiniteDifferences) {
    RandomGeometry g(9);
    for (int trial = 0; trial < 60; ++trial) {
        const Surface s = g.surface(g.integer(1, 4), g.integer(1, 4), 6, 7, trial % 2 == 0);
        const Interval du = domain(s, Dir::u);
        const Interval dv = domain(s, Dir::v);
        const double u = g.uniform(du.lo, du.hi), v = g.uniform(dv.lo, dv.hi), h = 1e-5;
        bool bad = u - 2 * h < du.lo || u + 2 * h > du.hi || v - 2 * h < dv.lo || v + 2 * h > dv.hi;
        for (double k : s.knots_u) bad |= std::abs(k - u) < 3 * h;
        for (double k : s.knots_v) bad |= std::abs(k - v) < 3 * h;
        if (bad) continue;
        const auto S = *surface_derivatives(s, u, v, 3);
        const auto Su = *surface_derivatives(s, u + h, v, 2),
                   Sm = *surface_derivatives(s, u - h, v, 2);
        const auto Sv = *surface_derivatives(s, u, v + h, 2),
                   Sn = *surface_derivatives(s, u, v - h, 2);
        for (int a = 0; a <= 2; ++a) {
            for (int b = 0; a + b <= 2; ++b) {
                const glm::dvec3 fdu = (Su.D[a][b] - Sm.D[a][b]) / (2 * h);
                const glm::dvec3 fdv = (Sv.D[a][b] - Sn.D[a][b]) / (2 * h);
                EXPECT_LT(glm::length(fdu - S.D[a + 1][b]) / (1 + glm::length(S.D[a + 1][b])),
                          1e-4);
                EXPECT_LT(glm::length(fdv - S.D[a][b + 1]) / (1 + glm::length(S.D[a][b + 1])),
                          1e-4);
            }
        }
    }
}

TEST(Evaluate, UnitWeightsEqualTheBSpline) {
    RandomGeometry g(13);
    Surface s = g.surface(3, 2, 6, 5, false);
    Surface r = s;
    r.type = SplineType::nurbs;
    for (double u : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        const Interval du = domain(s.knots_u, 3, 6), dv = domain(s.knots_v, 2, 5);
        const double uu = du.lo + u * (du.hi - du.lo), vv = dv.lo + (1 - u) * (dv.hi - dv.lo);
        const auto a = *surface_derivatives(s, uu, vv, 2), b = *surface_derivatives(r, uu, vv, 2);
        for (int i = 0; i <= 2; ++i)
            for (int j = 0; i + j <= 2; ++j) EXPECT_EQ(a.D[i][j], b.D[i][j]);
    }
}

TEST(Evaluate, AffineInvariance) {
    RandomGeometry g(17);
    Surface s = g.surface(3, 3, 5, 5, true);
    Surface m = s;
    const glm::dmat3 A{{0.5, 1, 0}, {-1, 2, 0.3}, {0, 0.1, 1.5}};
    const glm::dvec3 shift{1, -2, 3};
    for (auto& p : m.points) p = A * p + shift;
    for (double u : {0.0, 0.3, 0.71, 1.0}) {
        for (double v : {0.0, 0.45, 1.0}) {
            const Interval du = domain(s.knots_u, 3, 5), dv = domain(s.knots_v, 3, 5);
            const double uu = du.lo + u * (du.hi - du.lo), vv = dv.lo + v * (dv.hi - dv.lo);
            expect_near(*surface_point(m, uu, vv), A * *surface_point(s, uu, vv) + shift, 1e-11);
        }
    }
}

TEST(Evaluate, ZeroDenominatorMeansNoPoint) {
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {{0, 0, 0}, {1, 0, 0}};
    c.weights = {1, -1};
    EXPECT_FALSE(curve_point(c, 0.5).has_value());
    EXPECT_FALSE(curve_derivatives(c, 0.5, 2).has_value());
    EXPECT_TRUE(curve_point(c, 0.25).has_value());
}

TEST(Evaluate, ZeroWeightControlPointHasNoInfluence) {
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 2;
    c.knots = bezier_knots(2);
    c.points = {{0, 0, 0}, {100, 100, 100}, {2, 0, 0}};
    c.weights = {1, 0, 1};
    // With w1 = 0 the curve is the line segment between the end points.
    for (double t : {0.1, 0.5, 0.9}) EXPECT_NEAR(curve_point(c, t)->y, 0.0, 1e-15);
}

TEST(Evaluate, RightLimitAtInteriorKnotLeftLimitAtEnd) {
    // Shared example 0053: full-multiplicity knot at 0.5 in u.
    Surface s;
    s.type = SplineType::bspline;
    s.degree_u = 2;
    s.degree_v = 1;
    s.n_u = 6;
    s.n_v = 2;
    s.knots_u = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
    s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 2}, {2, 0, 0}, {2, 1, 0},
                {3, 0, 1}, {3, 1, 1}, {4, 0, 0}, {4, 1, 2}, {5, 0, 1}, {5, 1, 0}};
    s.weights.assign(12, 1.0);
    const auto d = *surface_derivatives(s, 0.5, 0.3, 2);
    expect_near(d.D[0][0], {3, 0.3, 1}, 1e-15);
    expect_near(d.D[1][0], {4, 0, -1.6}, 1e-14);
    expect_near(d.D[2][0], {0, 0, 4}, 1e-13);
    expect_near(d.D[1][1], {0, 0, 8}, 1e-13);
    const auto e = *surface_derivatives(s, 1, 1, 2);
    expect_near(e.D[2][0], {0, 0, -24}, 1e-12);
    expect_near(*surface_normal(s, 0.5, 0.3), {0.3713906763541038, 0.0, 0.9284766908852594}, 1e-15);
}

namespace {
// A degree (2,1) patch whose edge u = 0 collapses to one point (a cone-like apex).
Surface apex_surface() {
    Surface s;
    s.type = SplineType::bspline;
    s.degree_u = 2;
    s.degree_v = 1;
    s.n_u = 3;
    s.n_v = 2;
    s.knots_u = bezier_knots(2);
    s.knots_v = bezier_knots(1);
    s.points = {{0, 0, 1}, {0, 0, 1}, {1, 0, 0.5}, {1, 1, 0.5}, {2, 0, 0}, {2, 2, 0}};
    s.weights.assign(6, 1.0);
    return s;
}
} // namespace

TEST(Evaluate, DegenerateNormalIsAbsentStrictlyButHasALimit) {
    const Surface s = apex_surface();
    EXPECT_FALSE(surface_normal(s, 0.0, 0.5).has_value());
    const glm::dvec3 limit = surface_normal_or_limit(s, 0.0, 0.5);
    const glm::dvec3 near = *surface_normal(s, 1e-7, 0.5);
    EXPECT_NEAR(glm::length(limit), 1.0, 1e-12);
    EXPECT_GT(glm::dot(limit, near), 1.0 - 1e-6);
}
