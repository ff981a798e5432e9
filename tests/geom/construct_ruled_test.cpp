// The ruled surface: S(u, v) = (1 - v) C0(u) + v C1(u), and the paper's hyperboloid.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/construct.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/validate.hpp"
#include "tests/geom/construct_test_util.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::point_at_unit;
using isoparm::testing::RandomGeometry;
using isoparm::testing::samples;

TEST(Ruled, MatchesTheDefiningFormulaForNonRationalCurves) {
    RandomGeometry g(611);
    for (int trial = 0; trial < 60; ++trial) {
        const int p0 = g.integer(1, 4), p1 = g.integer(1, 4);
        const Curve c0 = g.curve(p0, g.integer(p0 + 1, p0 + 5), false, trial % 3 != 0);
        const Curve c1 = g.curve(p1, g.integer(p1 + 1, p1 + 5), false, trial % 2 == 0);
        auto r = ruled(c0, c1);
        ASSERT_TRUE(r.ok()) << r.error().message;
        const Surface& s = *r;
        ASSERT_TRUE(validate_surface(s).ok());
        EXPECT_EQ(s.degree_v, 1);
        EXPECT_EQ(s.knots_v, (Knots{0, 0, 1, 1}));
        EXPECT_EQ(s.knots_u.front(), 0.0);
        EXPECT_EQ(s.knots_u.back(), 1.0);
        for (double u : samples(0, 1, 20)) {
            const glm::dvec3 a = *point_at_unit(c0, u), b = *point_at_unit(c1, u);
            for (double v : samples(0, 1, 8)) {
                const auto S = surface_point(s, u, v);
                ASSERT_TRUE(S.has_value());
                EXPECT_LT(glm::distance(*S, (1 - v) * a + v * b), 1e-10) << u << "," << v;
            }
        }
    }
}

TEST(Ruled, RationalCurvesGiveStraightSegmentsBetweenThem) {
    RandomGeometry g(612);
    for (int trial = 0; trial < 40; ++trial) {
        const Curve c0 = g.curve(2, g.integer(3, 6), true, trial % 2 == 0);
        const Curve c1 = g.curve(3, g.integer(4, 7), true);
        auto r = ruled(c0, c1);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ(r->type, SplineType::nurbs);
        for (double u : samples(0, 1, 16)) {
            const glm::dvec3 a = *point_at_unit(c0, u), b = *point_at_unit(c1, u);
            EXPECT_LT(glm::distance(*surface_point(*r, u, 0), a), 1e-9);
            EXPECT_LT(glm::distance(*surface_point(*r, u, 1), b), 1e-9);
            double last = 0;
            for (double v : samples(0, 1, 8)) {
                // On the segment a-b, moving monotonically from a to b (positive weights).
                const glm::dvec3 S = *surface_point(*r, u, v);
                const double t = glm::dot(S - a, b - a) / glm::dot(b - a, b - a);
                EXPECT_LT(glm::distance(S, a + t * (b - a)), 1e-9);
                EXPECT_GE(t, last - 1e-12);
                last = t;
            }
        }
    }
}

// The paper's Figure 7: two circles, the lower one rotated, ruled into a hyperboloid of one
// sheet. A ruling from angle theta + alpha at z = -h to theta at z = h has its midpoint at
// radius r cos(alpha / 2), so x^2 + y^2 - c z^2 = d with d = r^2 cos^2(alpha / 2) and
// c = r^2 sin^2(alpha / 2) / h^2.
TEST(Ruled, PaperHyperboloidOfOneSheet) {
    const double r = 2.0, h = 1.5, alpha = 70.0;
    auto lower = circular_arc({0, 0, -h}, r, alpha, alpha + 360.0, Plane::xy);
    auto upper = full_circle({0, 0, h}, r, Plane::xy);
    ASSERT_TRUE(lower.ok() && upper.ok());
    auto s = ruled(*lower, *upper);
    ASSERT_TRUE(s.ok()) << s.error().message;
    const double half = alpha * M_PI / 360.0;
    const double d = r * r * std::cos(half) * std::cos(half);
    const double c = r * r * std::sin(half) * std::sin(half) / (h * h);
    double min_radius = 1e9;
    for (double u : samples(0, 1, 90)) {
        for (double v : samples(0, 1, 30)) {
            const glm::dvec3 P = *surface_point(*s, u, v);
            EXPECT_NEAR(P.x * P.x + P.y * P.y - c * P.z * P.z, d, 1e-12) << u << "," << v;
            min_radius = std::min(min_radius, std::hypot(P.x, P.y));
        }
    }
    // The waist: a real hyperboloid (not a cylinder, not a cone).
    EXPECT_NEAR(min_radius, r * std::cos(half), 1e-12);
}

TEST(Ruled, PropagatesCompatibilityErrorsAtTheCurve) {
    Curve a;
    a.type = SplineType::nurbs;
    a.degree = 1;
    a.knots = {0, 0, 1, 1};
    a.points = {{0, 0, 0}, {1, 0, 0}};
    a.weights = {1, -1};
    Curve b = a;
    b.type = SplineType::bspline;
    b.knots = {0, 0, 0.5, 1, 1};
    b.points = {{0, 0, 1}, {1, 0, 1}, {2, 0, 1}};
    b.weights = {1, 1, 1};
    auto r = ruled(a, b);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::weights);
    EXPECT_EQ(r.error().path, "/curves/0");
}
