// De Boor's triangle: its last point is the curve point; correct at knots of any multiplicity.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/deboor.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

TEST(DeBoor, LastLevelIsTheCurvePointEverywhereIncludingKnots) {
    RandomGeometry g(21);
    for (int trial = 0; trial < 100; ++trial) {
        const int p = g.integer(1, 7);
        const Curve c = g.curve(p, g.integer(p + 1, p + 9), trial % 2 == 0, trial % 4 != 0, p + 1);
        const Interval dom = domain(c.knots, p, c.count());
        std::vector<double> ts{dom.lo, dom.hi, g.uniform(dom.lo, dom.hi)};
        for (int k = p; k <= c.count(); ++k) ts.push_back(c.knots[k]);
        for (double t : ts) {
            const DeBoorTriangle tri = deboor_curve(c, t);
            ASSERT_EQ(static_cast<int>(tri.levels.size()), p + 1);
            for (int k = 0; k <= p; ++k)
                ASSERT_EQ(static_cast<int>(tri.levels[k].size()), p + 1 - k);
            const glm::dvec3 a = *DeBoorTriangle::cartesian(tri.levels[p][0]);
            const glm::dvec3 b = *curve_point(c, t);
            EXPECT_NEAR(glm::length(a - b), 0.0, 1e-11 * (1 + glm::length(b))) << "t=" << t;
        }
    }
}

TEST(DeBoor, ReferenceExampleAtFullMultiplicityKnot) {
    // Shared example 0042: degree 2, U = {0,0,0,1,1,1,2,2,2}, t = 1 -> first_index 3.
    Curve c;
    c.degree = 2;
    c.knots = {0, 0, 0, 1, 1, 1, 2, 2, 2};
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 3, 0}, {4, 4, 0}, {5, 3, 0}};
    c.weights.assign(6, 1.0);
    const DeBoorTriangle tri = deboor_curve(c, 1.0);
    EXPECT_EQ(tri.first_index, 3);
    EXPECT_EQ(glm::dvec3(tri.levels[1][0]), glm::dvec3(3, 3, 0));
    EXPECT_EQ(glm::dvec3(tri.levels[1][1]), glm::dvec3(4, 4, 0));
    EXPECT_EQ(glm::dvec3(tri.levels[2][0]), glm::dvec3(3, 3, 0));
}

TEST(DeBoor, SurfaceTraceMatchesEvaluation) {
    RandomGeometry g(23);
    for (int trial = 0; trial < 40; ++trial) {
        const Surface s = g.surface(g.integer(1, 4), g.integer(1, 4), 6, 5, trial % 2 == 0);
        const Interval du = domain(s, Dir::u);
        const Interval dv = domain(s, Dir::v);
        const double u = g.uniform(du.lo, du.hi),
                     v = trial % 5 == 0 ? dv.hi : g.uniform(dv.lo, dv.hi);
        const DeBoorSurfaceTrace tr = deboor_surface(s, u, v);
        ASSERT_EQ(static_cast<int>(tr.u_stage.size()), s.n_v);
        EXPECT_EQ(static_cast<int>(tr.v_stage.levels[0].size()), s.degree_v + 1);
        const glm::dvec3 a = *tr.point(), b = *surface_point(s, u, v);
        EXPECT_NEAR(glm::length(a - b), 0.0, 1e-11 * (1 + glm::length(b)));
    }
}

TEST(DeBoor, ZeroWeightLevelPointIsAbsent) {
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 1;
    c.knots = {0, 0, 1, 1};
    c.points = {{0, 0, 0}, {1, 0, 0}};
    c.weights = {1, -1};
    const DeBoorTriangle tri = deboor_curve(c, 0.5);
    EXPECT_FALSE(DeBoorTriangle::cartesian(tri.levels[1][0]).has_value());
    EXPECT_TRUE(DeBoorTriangle::cartesian(tri.levels[0][0]).has_value());
}
