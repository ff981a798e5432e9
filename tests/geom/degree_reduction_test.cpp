// Degree reduction (A5.11): elevating then reducing gives the original back with a zero bound
// (rational too, surfaces in either direction); the bound is a true bound; a reduction beyond
// the tolerance is refused with the bound.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/degree_reduction.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/validate.hpp"
#include "tests/support/random_geometry.hpp"
#include "tests/support/sampled_distance.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;
using isoparm::testing::sampled_distance;

TEST(ReduceDegree, UndoesElevation) {
    RandomGeometry g(9401);
    for (int trial = 0; trial < 200; ++trial) {
        const int p = g.integer(1, 7);
        const bool rational = trial % 2 == 1;
        // Interior knots up to multiplicity p (C0 joins) and, in every fifth trial, one of
        // multiplicity p + 1 (a join where the curve may jump).
        Curve c = g.curve(p, g.integer(p + 1, p + 9), rational, true, p);
        if (trial % 5 == 0 && c.count() > p + 1) {
            const double t = c.knots[p + 1];
            if (multiplicity(c.knots, t) < p) c = *insert_knot(c, t, p - multiplicity(c.knots, t));
            const int f = static_cast<int>(std::lower_bound(c.knots.begin(), c.knots.end(), t) -
                                           c.knots.begin());
            c.knots.insert(c.knots.begin() + f, t); // the curve jumps: a point of its own
            c.points.insert(c.points.begin() + (f - 1), c.points[f - 1] + glm::dvec3(0, 0, 1));
            c.weights.insert(c.weights.begin() + (f - 1), c.weights[f - 1]);
            ASSERT_TRUE(validate_curve(c).ok()) << validate_curve(c).error().message;
        }
        auto elevated = elevate_degree(c, 1);
        ASSERT_TRUE(elevated.ok());
        auto r = reduce_degree(*elevated, 1e-9);
        ASSERT_TRUE(r.ok()) << "trial " << trial << ": " << r.error().message;
        EXPECT_LE(r->max_error, 1e-9);
        const Curve& back = r->curve;
        ASSERT_TRUE(validate_curve(back).ok());
        EXPECT_EQ(back.degree, p);
        ASSERT_EQ(back.knots.size(), c.knots.size()) << "trial " << trial;
        for (size_t k = 0; k < c.knots.size(); ++k) EXPECT_EQ(back.knots[k], c.knots[k]);
        for (int i = 0; i < c.count(); ++i) {
            EXPECT_LT(glm::distance(back.points[i], c.points[i]), 1e-9) << trial << ": " << i;
            EXPECT_NEAR(back.weights[i], c.weights[i], 1e-9);
        }
        EXPECT_EQ(back.type, c.type);
    }
}

TEST(ReduceDegree, UndoesElevationOfSurfacesInEitherDirection) {
    RandomGeometry g(9402);
    for (int trial = 0; trial < 16; ++trial) {
        const Dir dir = trial % 2 == 0 ? Dir::u : Dir::v;
        const Surface s = g.surface(g.integer(1, 4), g.integer(1, 4), 6, 5, trial % 4 >= 2);
        auto elevated = elevate_degree(s, dir, 1);
        ASSERT_TRUE(elevated.ok());
        auto r = reduce_degree(*elevated, dir, 1e-9);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_LE(r->max_error, 1e-9);
        ASSERT_TRUE(validate_surface(r->surface).ok());
        EXPECT_EQ(r->surface.degree_u, s.degree_u);
        EXPECT_EQ(r->surface.degree_v, s.degree_v);
        EXPECT_EQ(r->surface.knots(dir), s.knots(dir));
        ASSERT_EQ(r->surface.points.size(), s.points.size());
        for (size_t k = 0; k < s.points.size(); ++k)
            EXPECT_LT(glm::distance(r->surface.points[k], s.points[k]), 1e-9);
    }
}

TEST(ReduceDegree, UnclampedAndBezierInputs) {
    RandomGeometry g(9403);
    const Curve open = g.curve(3, 7, false, false);
    auto elevated = elevate_degree(open, 1); // clamps first
    ASSERT_TRUE(elevated.ok());
    auto r = reduce_degree(*elevated, 1e-9);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_LT(sampled_distance(open, r->curve), 1e-9);

    Curve bezier = g.curve(4, 5, true);
    bezier.type = SplineType::rational_bezier;
    bezier.knots = bezier_knots(4);
    auto up = elevate_degree(bezier, 1);
    ASSERT_TRUE(up.ok());
    auto down = reduce_degree(*up, 1e-9);
    ASSERT_TRUE(down.ok());
    EXPECT_EQ(down->curve.type, SplineType::rational_bezier);
    EXPECT_EQ(down->curve.knots, bezier_knots(4));
}

TEST(ReduceDegree, TheBoundHoldsAndIsEquation545ForAQuadratic) {
    // P0, P1, P2 -> the chord P0 P2: bound |P1 - (P0 + P2)/2| = 2; the parabola's largest
    // distance from the chord is half of it, at t = 1/2.
    Curve c;
    c.type = SplineType::bezier;
    c.degree = 2;
    c.knots = bezier_knots(2);
    c.points = {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}};
    c.weights.assign(3, 1.0);
    auto r = reduce_degree(c, 5.0);
    ASSERT_TRUE(r.ok());
    EXPECT_DOUBLE_EQ(r->max_error, 2.0);
    EXPECT_NEAR(sampled_distance(c, r->curve), 1.0, 1e-12);

    RandomGeometry g(9404);
    for (int trial = 0; trial < 60; ++trial) {
        const int p = g.integer(2, 7);
        Curve any = g.curve(p, g.integer(p + 1, p + 6), trial % 2 == 1, true, p);
        if (is_rational(any.type)) {
            // A rational bound needs the 4D bound below the smallest weight: an elevated curve,
            // disturbed a little.
            any = *elevate_degree(g.curve(p - 1, g.integer(p, p + 5), true, true, p - 1), 1);
            for (glm::dvec3& q : any.points)
                q += glm::dvec3(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)) * 1e-3;
        }
        auto loose = reduce_degree(any, 1e300);
        ASSERT_TRUE(loose.ok()) << loose.error().message;
        EXPECT_LE(sampled_distance(any, loose->curve), loose->max_error * (1 + 1e-9) + 1e-12)
            << "trial " << trial;
    }
}

TEST(ReduceDegree, RefusesBeyondTheToleranceWithTheBound) {
    Curve c;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 2, 0}, {2, -2, 0}, {3, 0, 0}};
    c.weights.assign(4, 1.0);
    auto r = reduce_degree(c, 1e-9);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::geometry);
    EXPECT_EQ(r.error().path, "/curve");
    auto loose = reduce_degree(c, 1e3);
    ASSERT_TRUE(loose.ok());
    EXPECT_NE(r.error().message.find(format_number(loose->max_error)), std::string::npos)
        << r.error().message;

    Curve line = c;
    line.degree = 1;
    line.knots = {0, 0, 1, 2, 3, 3};
    r = reduce_degree(line, 1e-9);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::degree);
    EXPECT_EQ(r.error().path, "/curve/degree");
    r = reduce_degree(c, -1);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/tolerance");
}

TEST(ReduceDegree, ASimpleKnotDisappearsAsElevationWouldHaveMadeIt) {
    // A cubic with simple knots that is one quadratic polynomial: reduced exactly, knots gone.
    Curve quadratic;
    quadratic.type = SplineType::bspline;
    quadratic.degree = 2;
    quadratic.knots = bezier_knots(2);
    quadratic.points = {{0, 0, 0}, {1, 2, 0}, {3, 1, 1}};
    quadratic.weights.assign(3, 1.0);
    Curve cubic = *elevate_degree(quadratic, 1);
    cubic = *insert_knot(cubic, 0.3, 1);
    cubic = *insert_knot(cubic, 0.7, 1);
    auto r = reduce_degree(cubic, 1e-9);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_EQ(r->curve.knots, bezier_knots(2));
    EXPECT_LT(sampled_distance(quadratic, r->curve), 1e-12);
}
