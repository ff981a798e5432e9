// The surface of revolution: each profile point turned about the z-axis, exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/construct.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "tests/geom/construct_test_util.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;
using isoparm::testing::samples;

namespace {

// The angle turned from a to b about z, in [0, 2 pi).
double turn(const glm::dvec3& a, const glm::dvec3& b) {
    double t = std::atan2(a.x * b.y - a.y * b.x, a.x * b.x + a.y * b.y);
    return t < -1e-12 ? t + 2 * M_PI : std::max(t, 0.0);
}

// Every sample: radius and height of the profile, angle from 0 to `degrees` monotonically,
// exact angles at v = 0, the arc knots and v = 1.
void expect_revolution(const Curve& profile, double degrees, const Surface& s, double tol) {
    ASSERT_TRUE(validate_surface(s).ok()) << validate_surface(s).error().message;
    const Interval du = domain(s, Dir::u);
    const Interval dp = domain(profile);
    EXPECT_EQ(du.lo, dp.lo);
    EXPECT_EQ(du.hi, dp.hi);
    EXPECT_EQ(s.knots_v.front(), 0.0);
    EXPECT_EQ(s.knots_v.back(), 1.0);
    const double total = degrees * M_PI / 180.0;
    const int arcs = (s.n_v - 1) / 2;
    for (double u : samples(du.lo, du.hi, 24)) {
        const auto C = curve_point(profile, u);
        ASSERT_TRUE(C.has_value());
        const double radius = std::hypot(C->x, C->y);
        double last = 0;
        for (double v : samples(0, 1, 48)) {
            const auto S = surface_point(s, u, v);
            ASSERT_TRUE(S.has_value());
            EXPECT_NEAR(std::hypot(S->x, S->y), radius, tol) << u << "," << v;
            EXPECT_NEAR(S->z, C->z, tol);
            if (radius < 1e-6) continue; // a pole: no angle
            double phi = turn(*C, *S);
            if (v == 1.0 && degrees == 360.0 && phi < 1.0) phi += 2 * M_PI;
            EXPECT_GE(phi, last - 1e-9) << u << "," << v;
            EXPECT_LE(phi, total + 1e-9);
            last = phi;
        }
        for (int k = 0; k <= arcs; ++k) { // exact angles at the arc joins
            const double v = static_cast<double>(k) / arcs;
            const glm::dvec3 S = *surface_point(s, u, v);
            const double want = total * k / arcs;
            const glm::dvec3 R{C->x * std::cos(want) - C->y * std::sin(want),
                               C->x * std::sin(want) + C->y * std::cos(want), C->z};
            EXPECT_LT(glm::distance(S, R), tol) << "k=" << k;
        }
    }
}

} // namespace

TEST(Revolve, RandomProfilesAtEveryArcCount) {
    RandomGeometry g(621);
    const double angles[] = {30, 90, 90.5, 120, 180, 200, 270, 300, 359, 360};
    int trial = 0;
    for (double angle : angles) {
        for (int rep = 0; rep < 6; ++rep, ++trial) {
            const int p = g.integer(1, 4);
            const Curve c = g.curve(p, g.integer(p + 1, p + 5), trial % 2 == 0, trial % 3 != 0);
            auto s = revolve(c, angle);
            ASSERT_TRUE(s.ok()) << s.error().message;
            EXPECT_EQ(s->type, SplineType::nurbs);
            EXPECT_EQ(s->degree_v, 2);
            expect_revolution(c, angle, *s, 1e-9);
        }
    }
}

// The paper's Figure 8: an 11-point degree-3 profile with 15 uniformly spaced clamped knots.
TEST(Revolve, PaperElevenPointProfile) {
    Curve c;
    c.degree = 3;
    c.knots = clamped_uniform_knots(11, 3);
    ASSERT_EQ(c.knots.size(), 15u);
    c.points = {{0, 0, 0},     {1.2, 0, 0},   {1.5, 0, 0.4}, {1.0, 0, 1.0},
                {0.6, 0, 1.6}, {0.7, 0, 2.2}, {1.3, 0, 2.6}, {1.6, 0, 3.2},
                {1.2, 0, 3.6}, {0.8, 0, 3.8}, {0.9, 0, 4.0}};
    c.weights.assign(11, 1.0);
    auto s = revolve(c, 360.0);
    ASSERT_TRUE(s.ok()) << s.error().message;
    EXPECT_EQ(s->n_u, 11);
    EXPECT_EQ(s->n_v, 9);
    EXPECT_EQ(s->knots_v, (Knots{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}));
    expect_revolution(c, 360.0, *s, 1e-12);
    // Closed: the seam v = 0 and v = 1 are the same curve, bit for bit.
    for (int i = 0; i < s->n_u; ++i) EXPECT_EQ(s->point(i, 0), s->point(i, s->n_v - 1));
    // The first control point is on the axis: a pole.
    for (double v : samples(0, 1, 10)) EXPECT_LT(glm::length(*surface_point(*s, 0, v)), 1e-15);
}

TEST(Revolve, AngleOutOfRangeIsSchema) {
    RandomGeometry g(622);
    const Curve c = g.curve(2, 4, false);
    for (double angle : {0.0, -10.0, 360.0001, 720.0, std::nan("")}) {
        auto s = revolve(c, angle);
        ASSERT_FALSE(s.ok()) << angle;
        EXPECT_EQ(s.error().code, ErrorCode::schema);
        EXPECT_EQ(s.error().path, "/angle");
    }
    EXPECT_TRUE(revolve(c, 1e-9).ok());
}
