// Knot removal (A5.8): inserting then removing gives the original back (rational too), an
// essential knot stays, and no reported removal moves the shape beyond the tolerance.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knot_removal.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/validate.hpp"
#include "tests/support/random_geometry.hpp"
#include "tests/support/sampled_distance.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;
using isoparm::testing::sampled_distance;

namespace {

void expect_same_net(const Curve& a, const Curve& b, double tol) {
    ASSERT_EQ(a.knots.size(), b.knots.size());
    ASSERT_EQ(a.count(), b.count());
    for (size_t k = 0; k < a.knots.size(); ++k) EXPECT_NEAR(a.knots[k], b.knots[k], 1e-15);
    for (int i = 0; i < a.count(); ++i) {
        EXPECT_LT(glm::distance(a.points[i], b.points[i]), tol) << i;
        EXPECT_NEAR(a.weights[i], b.weights[i], tol) << i;
    }
}

} // namespace

TEST(RemoveKnot, UndoesInsertion) {
    RandomGeometry g(9301);
    for (int trial = 0; trial < 200; ++trial) {
        const int p = g.integer(1, 6);
        const bool rational = trial % 2 == 1;
        const Curve c = g.curve(p, g.integer(p + 1, p + 8), rational, true, p);
        const Interval d = domain(c.knots, p, c.count());
        // A new knot, or one already there (its multiplicity raised).
        double t = g.uniform(d.lo, d.hi);
        if (trial % 3 == 0 && c.count() > p + 1) t = c.knots[g.integer(p + 1, c.count() - 1)];
        const int room = p - multiplicity(c.knots, t);
        if (room < 1 || !(d.lo < t && t < d.hi)) continue;
        const int times = g.integer(1, room);
        auto inserted = insert_knot(c, t, times);
        ASSERT_TRUE(inserted.ok());
        auto removed = remove_knot(*inserted, t, times, 1e-9);
        ASSERT_TRUE(removed.ok()) << removed.error().message;
        EXPECT_EQ(removed->removed, times) << "trial " << trial;
        EXPECT_LE(removed->max_deviation, 1e-9);
        ASSERT_TRUE(validate_curve(removed->curve).ok());
        expect_same_net(removed->curve, c, 1e-9);
        EXPECT_EQ(removed->curve.type, c.type);
    }
}

TEST(RemoveKnot, KeepsAnEssentialKnot) {
    RandomGeometry g(9302);
    for (int trial = 0; trial < 50; ++trial) {
        const int p = g.integer(1, 5);
        const Curve c = g.curve(p, p + 4, trial % 2 == 1);
        const double t = c.knots[p + 2]; // an interior knot of random points: it matters
        auto r = remove_knot(c, t, 3, 1e-12);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ(r->removed, 0);
        EXPECT_EQ(r->max_deviation, 0.0);
        EXPECT_EQ(r->curve.knots, c.knots);
        EXPECT_EQ(r->curve.points, c.points);
    }
}

TEST(RemoveKnot, NeverReportsARemovalBeyondTheTolerance) {
    RandomGeometry g(9303);
    for (int trial = 0; trial < 100; ++trial) {
        const int p = g.integer(2, 5);
        Curve c = g.curve(p, p + 6, trial % 2 == 1, true, p);
        // Small noise on a removable knot: removals succeed or fail with the tolerance.
        const double t = g.uniform(c.knots[p] + 0.01, c.knots[c.count()] - 0.01);
        Curve refined = *insert_knot(c, t, g.integer(1, p));
        for (glm::dvec3& q : refined.points)
            q += glm::dvec3(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)) * 1e-3;
        const double tolerance = std::pow(10.0, g.uniform(-4, -1));
        auto r = remove_knot(refined, t, p + 1, tolerance);
        ASSERT_TRUE(r.ok());
        EXPECT_LE(r->max_deviation, tolerance);
        // An independent dense sample agrees (up to what the sampling may miss).
        EXPECT_LE(sampled_distance(refined, r->curve), tolerance * 1.05) << "trial " << trial;
        EXPECT_EQ(r->curve.count(), refined.count() - r->removed);
    }
}

TEST(RemoveKnot, SurfacesUndoInsertionInEitherDirection) {
    RandomGeometry g(9304);
    for (int trial = 0; trial < 24; ++trial) {
        const bool rational = trial % 2 == 1;
        const Dir dir = trial % 4 < 2 ? Dir::u : Dir::v;
        const Surface s = g.surface(g.integer(1, 4), g.integer(1, 4), 6, 5, rational);
        const int p = s.degree(dir);
        const Interval d = domain(s.knots(dir), p, s.count(dir));
        const double t = g.uniform(d.lo, d.hi);
        const int times = g.integer(1, p);
        auto inserted = insert_knot(s, dir, t, times);
        ASSERT_TRUE(inserted.ok());
        auto r = remove_knot(*inserted, dir, t, times, 1e-9);
        ASSERT_TRUE(r.ok()) << r.error().message;
        EXPECT_EQ(r->removed, times);
        ASSERT_TRUE(validate_surface(r->surface).ok());
        EXPECT_EQ(r->surface.n_u, s.n_u);
        EXPECT_EQ(r->surface.n_v, s.n_v);
        for (size_t k = 0; k < s.points.size(); ++k) {
            EXPECT_LT(glm::distance(r->surface.points[k], s.points[k]), 1e-9);
            EXPECT_NEAR(r->surface.weights[k], s.weights[k], 1e-9);
        }
    }
}

TEST(RemoveKnot, ASurfaceRemovalCountsOnlyIfEveryLinePasses) {
    RandomGeometry g(9305);
    const Surface s = g.surface(3, 2, 6, 5, false);
    const double t = 0.5 * (s.knots_u[3] + s.knots_u[4]);
    Surface refined = *insert_knot(s, Dir::u, t, 1);
    // One column disturbed: the knot is essential there, so it stays everywhere.
    for (int i = 0; i < refined.n_u; ++i) refined.point(i, 2).z += 0.1 * (i % 2 == 0 ? 1 : -1);
    auto r = remove_knot(refined, Dir::u, t, 1, 1e-6);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->removed, 0);
    EXPECT_EQ(r->surface.points, refined.points);
    // With a tolerance that covers the disturbance the removal goes through, within it.
    auto loose = remove_knot(refined, Dir::u, t, 1, 1.0);
    ASSERT_TRUE(loose.ok());
    EXPECT_EQ(loose->removed, 1);
    EXPECT_LE(loose->max_deviation, 1.0);
    EXPECT_LE(sampled_distance(refined, loose->surface), 1.0);
}

TEST(RemoveKnot, RefusesValuesThatAreNotInteriorKnots) {
    Curve c;
    c.degree = 2;
    c.knots = {0, 0, 0, 0.5, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}};
    c.weights.assign(4, 1.0);
    auto r = remove_knot(c, 0.25, 1, 1e-9);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/knot");
    for (double end : {0.0, 1.0, 2.0}) {
        r = remove_knot(c, end, 1, 1e-9);
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, ErrorCode::domain);
        EXPECT_EQ(r.error().path, "/knot");
    }
    r = remove_knot(c, 0.5, 1, -1e-3);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/tolerance");
    r = remove_knot(c, 0.5, 0, 1e-9);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/times");
}

TEST(RemoveKnot, MergesTheTwoPointsOfAContinuousFullMultiplicityKnot) {
    // Degree 2 with 0.5 at multiplicity 3 where the two pieces meet (P2 = P3): removing one copy
    // leaves a C0 curve with the knot at multiplicity 2.
    Curve c;
    c.degree = 2;
    c.knots = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}, {2, 0, 0}, {3, 3, 0}, {4, 0, 0}};
    c.weights.assign(6, 1.0);
    auto r = remove_knot(c, 0.5, 3, 1e-9);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r->removed, 1);
    EXPECT_EQ(multiplicity(r->curve.knots, 0.5), 2);
    EXPECT_LT(sampled_distance(c, r->curve), 1e-12);
}
