// Swung and swept surfaces against their formulas; the oriented sweep's deviation report.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/geom/construct.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/validate.hpp"
#include "tests/geom/construct_test_util.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;
using isoparm::testing::samples;

namespace {

Curve flattened(Curve c, int axis) {
    for (auto& p : c.points) p[axis] = 0.0;
    return c;
}

} // namespace

TEST(Swing, MatchesTheDefiningFormula) {
    RandomGeometry g(631);
    for (int trial = 0; trial < 60; ++trial) {
        const int p = g.integer(1, 4), q = g.integer(1, 4);
        const Curve P =
            flattened(g.curve(p, g.integer(p + 1, p + 5), trial % 2 == 0, trial % 3 != 0), 1);
        const Curve T =
            flattened(g.curve(q, g.integer(q + 1, q + 5), trial % 3 == 0, trial % 4 != 0), 2);
        const double scale = g.uniform(-2, 2);
        auto s = swing(P, T, scale);
        ASSERT_TRUE(s.ok()) << s.error().message;
        ASSERT_TRUE(validate_surface(*s).ok());
        EXPECT_EQ(is_rational(s->type), is_rational(P.type) || is_rational(T.type));
        const Interval du = domain(P), dv = domain(T);
        for (double u : samples(du.lo, du.hi, 16)) {
            const glm::dvec3 Pu = *curve_point(P, u);
            for (double v : samples(dv.lo, dv.hi, 16)) {
                const glm::dvec3 Tv = *curve_point(T, v);
                const glm::dvec3 want{scale * Pu.x * Tv.x, scale * Pu.x * Tv.y, Pu.z};
                const auto S = surface_point(*s, u, v);
                ASSERT_TRUE(S.has_value());
                EXPECT_LT(glm::distance(*S, want), 1e-9 * (1 + glm::length(want))) << u << "," << v;
            }
        }
    }
}

TEST(Swing, ACircleTrajectoryGivesASurfaceOfRevolution) {
    RandomGeometry g(632);
    const Curve P = flattened(g.curve(3, 6, false), 1);
    auto T = full_circle({0, 0, 0}, 1.0, Plane::xy);
    ASSERT_TRUE(T.ok());
    auto s = swing(P, *T, 1.0);
    ASSERT_TRUE(s.ok());
    for (double u : samples(domain(P).lo, domain(P).hi, 10))
        for (double v : samples(0, 1, 20)) {
            const glm::dvec3 S = *surface_point(*s, u, v), C = *curve_point(P, u);
            EXPECT_NEAR(std::hypot(S.x, S.y), std::abs(C.x), 1e-12);
            EXPECT_NEAR(S.z, C.z, 1e-12);
        }
}

TEST(Swing, CurvesOffTheirPlanesAreGeometryErrors) {
    RandomGeometry g(633);
    Curve P = flattened(g.curve(2, 5, false), 1);
    Curve T = flattened(g.curve(2, 4, false), 2);
    Curve badP = P;
    badP.points[3].y = 0.25;
    badP.points[4].y = 1.0;
    auto r = swing(badP, T, 1.0);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::geometry);
    EXPECT_EQ(r.error().path, "/profile/points/3");
    Curve badT = T;
    badT.points[1].z = -1e-3;
    r = swing(P, badT, 1.0);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::geometry);
    EXPECT_EQ(r.error().path, "/trajectory/points/1");
    r = swing(P, T, std::numeric_limits<double>::infinity());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/scale");
}

TEST(Sweep, MatchesTheDefiningFormulaForRationalAndUnclampedCurves) {
    RandomGeometry g(634);
    for (int trial = 0; trial < 60; ++trial) {
        const int p = g.integer(1, 4), q = g.integer(1, 4);
        const Curve P = g.curve(p, g.integer(p + 1, p + 5), trial % 2 == 0, trial % 3 != 0);
        const Curve T = g.curve(q, g.integer(q + 1, q + 5), trial % 3 != 1, trial % 4 != 0);
        auto s = sweep(P, T);
        ASSERT_TRUE(s.ok()) << s.error().message;
        ASSERT_TRUE(validate_surface(*s).ok());
        const Interval du = domain(P), dv = domain(T);
        EXPECT_EQ(s->knots_u, P.knots);
        EXPECT_EQ(s->knots_v, T.knots);
        const glm::dvec3 T0 = *curve_point(T, dv.lo);
        for (double u : samples(du.lo, du.hi, 16)) {
            const glm::dvec3 Pu = *curve_point(P, u);
            for (double v : samples(dv.lo, dv.hi, 16)) {
                const glm::dvec3 want = Pu + *curve_point(T, v) - T0;
                EXPECT_LT(glm::distance(*surface_point(*s, u, v), want), 1e-9) << u << "," << v;
            }
        }
    }
}

TEST(OrientedSweep, AStraightTrajectoryIsTheTranslationalSweep) {
    RandomGeometry g(635);
    const Curve P = g.curve(3, 6, true);
    Curve T = line_segment({1, 2, 3}, {4, -2, 5});
    auto o = oriented_sweep(P, T, {.sections = 4});
    ASSERT_TRUE(o.ok()) << o.error().message;
    EXPECT_LT(o->max_deviation, 1e-9);
    auto t = sweep(P, T);
    ASSERT_TRUE(t.ok());
    const Interval du = domain(P);
    for (double s : samples(0, 1, 12))
        for (double v : samples(0, 1, 12)) {
            const glm::dvec3 a = *surface_point(o->skinned.surface, s, v);
            const glm::dvec3 b = *surface_point(*t, du.lo + (du.hi - du.lo) * s, v);
            EXPECT_LT(glm::distance(a, b), 1e-9);
        }
}

// A small circle perpendicular to a big circular trajectory sweeps a torus: every point of the
// skin lies within the reported deviation of it, and more sections shrink the deviation.
TEST(OrientedSweep, ACircleAroundACircleIsATorusWithinTheReportedDeviation) {
    const double R = 3.0, r = 0.5;
    auto trajectory = full_circle({0, 0, 0}, R, Plane::xy);
    auto profile = circular_arc({R, 0, 0}, r, 0, 360, glm::dvec3{1, 0, 0}, glm::dvec3{0, 0, 1});
    ASSERT_TRUE(trajectory.ok() && profile.ok());
    double previous = 1e9;
    for (int sections : {4, 8, 16, 32}) {
        auto o = oriented_sweep(*profile, *trajectory, {.sections = sections});
        ASSERT_TRUE(o.ok()) << o.error().message;
        EXPECT_GT(o->max_deviation, 0.0);
        EXPECT_LT(o->max_deviation, previous);
        previous = o->max_deviation;
        double worst = 0;
        for (double u : samples(0, 1, 32))
            for (double v : samples(0, 1, 16 * sections)) {
                const glm::dvec3 S = *surface_point(o->skinned.surface, u, v);
                worst = std::max(worst, std::abs(std::hypot(std::hypot(S.x, S.y) - R, S.z) - r));
            }
        EXPECT_LE(worst, o->max_deviation * (1 + 1e-6) + 1e-12) << sections;
        std::printf("sections %d: reported %g, distance to the torus %g\n", sections,
                    o->max_deviation, worst);
        // The skin passes through every placed copy: the sections lie on the torus.
        for (int k = 0; k <= sections; ++k)
            for (double u : samples(0, 1, 16)) {
                const glm::dvec3 S = *surface_point(o->skinned.surface, u, double(k) / sections);
                EXPECT_NEAR(std::hypot(std::hypot(S.x, S.y) - R, S.z), r, 1e-9);
            }
    }
    // Sections at equal arc length: the cubic skin converges at fourth order (x16 per halving).
    EXPECT_LT(previous, 3e-4);
}

TEST(OrientedSweep, AStationaryStartTakesItsTangentFromTheChord) {
    // The first two control points coincide: T'(a) = 0, the tangent comes from a chord.
    Curve T;
    T.degree = 2;
    T.knots = {0, 0, 0, 1, 1, 1};
    T.points = {{0, 0, 0}, {0, 0, 0}, {0, 0, 4}};
    T.weights = {1, 1, 1};
    auto P = full_circle({0, 0, 0}, 1.0, Plane::xy);
    ASSERT_TRUE(P.ok());
    auto o = oriented_sweep(*P, T, {.sections = 6});
    ASSERT_TRUE(o.ok()) << o.error().message;
    // A straight trajectory: no turning, a cylinder of radius 1 around the z-axis. The
    // placement along it is only approximately at equal arc length near the stationary start
    // (the polyline inverts s = 4 t^2 linearly), which the report shows as a small deviation.
    EXPECT_LT(o->max_deviation, 1e-4);
    for (double u : samples(0, 1, 16))
        for (double v : samples(0, 1, 16)) {
            const glm::dvec3 S = *surface_point(o->skinned.surface, u, v);
            EXPECT_NEAR(std::hypot(S.x, S.y), 1.0, 1e-9);
        }
}

TEST(OrientedSweep, ErrorsNameTheOption) {
    RandomGeometry g(636);
    const Curve P = g.curve(2, 4, false);
    const Curve T = g.curve(2, 4, false);
    auto o = oriented_sweep(P, T, {.sections = 0});
    ASSERT_FALSE(o.ok());
    EXPECT_EQ(o.error().code, ErrorCode::schema);
    EXPECT_EQ(o.error().path, "/sections");
    o = oriented_sweep(P, T, {.sections = 2, .degree = 3});
    ASSERT_FALSE(o.ok());
    EXPECT_EQ(o.error().path, "/degree");
    Curve point = T;
    for (auto& p : point.points) p = {1, 1, 1};
    o = oriented_sweep(P, point, {});
    ASSERT_FALSE(o.ok());
    EXPECT_EQ(o.error().code, ErrorCode::geometry);
    EXPECT_EQ(o.error().path, "/trajectory");
}
