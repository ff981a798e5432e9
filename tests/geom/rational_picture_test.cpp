// The rational picture: the denominator against its definition, its zero set on w = 0 to
// rounding (and where closed forms say), isocurves against surface evaluation, and the
// homogeneous lift of a circle on the cone x^2 + y^2 = w^2.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/rational_picture.hpp"
#include "core/geom/tessellate.hpp"
#include "tests/support/random_geometry.hpp"
#include "tests/support/small_surfaces.hpp"

using namespace isoparm::geom;

using isoparm::testing::bilinear_patch;

TEST(RationalPicture, DenominatorIsTheWeightedBasisSum) {
    isoparm::testing::RandomGeometry g(41);
    for (int trial = 0; trial < 8; ++trial) {
        Surface s = g.surface(1 + trial % 3, 2 + trial % 2, 5, 6, true);
        for (double& w : s.weights) w = g.uniform(-2, 3);
        const ParamRect d = domain(s);
        for (int k = 0; k < 20; ++k) {
            const double u = g.uniform(d.u.lo, d.u.hi), v = g.uniform(d.v.lo, d.v.hi);
            const auto Nu = all_basis(s.knots_u, s.degree_u, s.n_u, u, 0)[0];
            const auto Nv = all_basis(s.knots_v, s.degree_v, s.n_v, v, 0)[0];
            double w = 0;
            for (int i = 0; i < s.n_u; ++i)
                for (int j = 0; j < s.n_v; ++j) w += Nu[i] * Nv[j] * s.weight(i, j);
            EXPECT_NEAR(surface_denominator(s, u, v), w, 1e-13);
        }
    }
    Surface plain = g.surface(3, 3, 4, 4, false);
    EXPECT_EQ(surface_denominator(plain, 0.3, 0.7), 1.0);
}

TEST(RationalPicture, ZeroSetOfALinearDenominatorIsItsLine) {
    // w = 1 - 2u: the surface goes to infinity along u = 1/2.
    const Surface s = bilinear_patch(1, 1, -1, -1);
    const auto segments = denominator_zero_set(s, 16);
    ASSERT_FALSE(segments.empty());
    double v_lo = 1, v_hi = 0;
    for (const ParamSegment& seg : segments)
        for (const glm::dvec2& p : {seg.a, seg.b}) {
            EXPECT_NEAR(p.x, 0.5, 1e-15);
            v_lo = std::min(v_lo, p.y);
            v_hi = std::max(v_hi, p.y);
        }
    EXPECT_EQ(v_lo, 0.0); // the line crosses the whole square
    EXPECT_EQ(v_hi, 1.0);
    EXPECT_EQ(segments.size(), 16u);
}

TEST(RationalPicture, ZeroSetOfASaddleDenominatorIsItsHyperbola) {
    // Corner weights 1, -2, -2, 1: w = 1 - 3u - 3v + 6uv = 6 (u - 1/2)(v - 1/2) - 1/2, zero on
    // the hyperbola (u - 1/2)(v - 1/2) = 1/12, one branch near each of two corners.
    const Surface s = bilinear_patch(1, -2, -2, 1);
    const auto segments = denominator_zero_set(s, 40);
    ASSERT_GT(segments.size(), 40u);
    for (const ParamSegment& seg : segments)
        for (const glm::dvec2& p : {seg.a, seg.b})
            EXPECT_NEAR((p.x - 0.5) * (p.y - 0.5), 1.0 / 12, 1e-14);
}

TEST(RationalPicture, ZeroSetEndpointsLieOnZeroToRounding) {
    isoparm::testing::RandomGeometry g(7);
    int crossings = 0;
    for (int trial = 0; trial < 10; ++trial) {
        Surface s = g.surface(2 + trial % 2, 2, 6, 5, true, true, 2);
        for (double& w : s.weights) w = g.uniform(-1, 2);
        for (const ParamSegment& seg : denominator_zero_set(s, 24)) {
            for (const glm::dvec2& p : {seg.a, seg.b}) {
                // |w| at the point is within a few ulps of the size of the weights.
                EXPECT_LT(std::abs(surface_denominator(s, p.x, p.y)), 1e-13) << trial;
                ++crossings;
            }
        }
    }
    EXPECT_GT(crossings, 100);
}

TEST(RationalPicture, PositiveWeightsHaveNoZeroSetAndOneSign) {
    isoparm::testing::RandomGeometry g(8);
    const Surface s = g.surface(3, 2, 6, 5, true);
    EXPECT_TRUE(denominator_zero_set(s, 32).empty());
    for (signed char c : denominator_signs(s, 16)) EXPECT_EQ(c, 1);
    const Surface half = bilinear_patch(1, 1, -1, -1);
    const auto signs = denominator_signs(half, 4); // u-major; w > 0 for u < 1/2
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_EQ(signs[i * 4 + j], i < 2 ? 1 : -1);
}

TEST(RationalPicture, IsocurveIsTheSurfaceWithOneParameterHeld) {
    isoparm::testing::RandomGeometry g(9);
    for (int trial = 0; trial < 12; ++trial) {
        const Surface s = g.surface(1 + trial % 4, 1 + (trial / 4) % 3, 6, 7, trial % 2 == 0);
        const ParamRect d = domain(s);
        for (Dir fixed : {Dir::u, Dir::v}) {
            const Interval held = fixed == Dir::u ? d.u : d.v;
            const Interval run = fixed == Dir::u ? d.v : d.u;
            const double t = g.uniform(held.lo, held.hi);
            const auto c = isocurve(s, fixed, t);
            ASSERT_TRUE(c);
            EXPECT_EQ(c->type, s.type);
            for (double r : uniform_params(run.lo, run.hi, 11)) {
                const auto a = fixed == Dir::u ? surface_point(s, t, r) : surface_point(s, r, t);
                const auto b = curve_point(*c, r);
                ASSERT_TRUE(a && b);
                EXPECT_LT(glm::distance(*a, *b), 1e-12 * (1 + glm::length(*a)));
            }
        }
    }
}

TEST(RationalPicture, IsocurveThroughAPointAtInfinityIsRefused) {
    // Weights 1 and -1 along u contract to 0 at u = 1/2 while w P does not.
    const Surface s = bilinear_patch(1, 1, -1, -1);
    EXPECT_FALSE(isocurve(s, Dir::u, 0.5));
    EXPECT_TRUE(isocurve(s, Dir::u, 0.25));
}

TEST(RationalPicture, LiftedCircleLiesOnTheConeAndProjectsToTheCircle) {
    // P&T A7.1's quarter arc: weights 1, cos 45, 1. Lifted to (w x, w y, w) it is a polynomial
    // (a parabola) on the cone x^2 + y^2 = w^2, and projecting it to w = 1 gives the circle.
    for (double sweep : {90.0, 180.0, 270.0, 360.0}) {
        const auto arc = circular_arc({0, 0, 0}, 1, 0, sweep, Plane::xy);
        ASSERT_TRUE(arc.ok());
        const Curve lifted = homogeneous_lift(*arc, {0, 1});
        EXPECT_EQ(lifted.type, SplineType::bspline);
        for (double t : uniform_params(0, 1, 41)) {
            const auto h = curve_point(lifted, t);
            const auto p = curve_point(*arc, t);
            ASSERT_TRUE(h && p);
            EXPECT_NEAR(h->x * h->x + h->y * h->y, h->z * h->z, 1e-14);
            EXPECT_NEAR(h->x / h->z, p->x, 1e-14);
            EXPECT_NEAR(h->y / h->z, p->y, 1e-14);
        }
    }
}

TEST(RationalPicture, GrevilleAbscissaIsTheMeanOfItsKnots) {
    const Knots U{0, 0, 0, 0, 0.25, 0.5, 1, 1, 1, 1};
    EXPECT_EQ(greville_abscissa(U, 3, 0), 0.0);
    EXPECT_DOUBLE_EQ(greville_abscissa(U, 3, 1), 0.25 / 3);
    EXPECT_DOUBLE_EQ(greville_abscissa(U, 3, 2), 0.75 / 3);
    EXPECT_DOUBLE_EQ(greville_abscissa(U, 3, 3), 1.75 / 3);
    EXPECT_EQ(greville_abscissa(U, 3, 5), 1.0);
}
