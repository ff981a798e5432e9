// The Homogeneous view's picture: every ray from the origin through a lifted point meets
// w = 1 at the projected point, and the lifted curve divided by w is the curve.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/primitives.hpp"
#include "ui/view/homogeneous_scene.hpp"

using namespace isoparm;
using namespace isoparm::ui;

TEST(HomogeneousScene, RaysThroughTheOriginProjectTheLiftedCurve) {
    const auto arc = geom::circular_arc({1, 2, 0}, 2, 0, 270, geom::Plane::xy);
    ASSERT_TRUE(arc.ok());
    const HomogeneousScene h = homogeneous_scene(*arc, {0, 1}, 0.4, 50);
    ASSERT_EQ(h.lifted_points.size(), arc->points.size());
    for (std::size_t k = 0; k < h.lifted_points.size(); ++k) {
        // Collinear with the origin: the lifted point is w times the projected one.
        EXPECT_LT(glm::length(glm::cross(h.lifted_points[k], h.projected_points[k])), 1e-14);
        EXPECT_EQ(h.lifted_points[k].z, arc->weights[k]);
    }
    ASSERT_EQ(h.lifted_curve.size(), 50u);
    ASSERT_EQ(h.projected_curve.size(), 1u);
    for (std::size_t k = 0; k < 50; ++k) {
        const glm::dvec3 q = h.lifted_curve[k] / h.lifted_curve[k].z;
        EXPECT_LT(glm::distance(q, h.projected_curve[0][k]), 1e-14);
        // On the circle of radius 2 about (1, 2).
        EXPECT_NEAR(glm::distance(glm::dvec2(q), glm::dvec2(1, 2)), 2, 1e-14);
    }
    ASSERT_TRUE(h.lifted_at_t && h.projected_at_t);
    EXPECT_LT(glm::distance(*h.lifted_at_t / h.lifted_at_t->z, *h.projected_at_t), 1e-14);
    EXPECT_LE(h.lo.z, 0.0); // the origin, the rays' centre, is in the picture
}

TEST(HomogeneousScene, NegativeWeightsBreakTheProjectedCurve) {
    geom::Curve c;
    c.type = geom::SplineType::rational_bezier;
    c.degree = 2;
    c.knots = {0, 0, 0, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
    c.weights = {1, -2, 1}; // w(t) = 1 - 6t + 6t^2: zero at two t, where C goes to infinity
    const HomogeneousScene h = homogeneous_scene(c, {0, 1}, 0.5, 101);
    EXPECT_EQ(h.lifted_curve.size(), 101u);  // the polynomial curve exists everywhere
    EXPECT_EQ(h.projected_curve.size(), 3u); // two passes through infinity
    // The lifted point at t = 1/2 has w = -1/2: below the origin, projecting through it.
    ASSERT_TRUE(h.lifted_at_t);
    EXPECT_DOUBLE_EQ(h.lifted_at_t->z, -0.5);
    EXPECT_LT(h.lifted_points[1].z, 0);
}

TEST(HomogeneousScene, OrbitKeepsWUpWithoutPitch) {
    const glm::dvec3 p = orbit_project({0, 0, 1}, 37, 0);
    EXPECT_DOUBLE_EQ(p.y, 1);
    EXPECT_DOUBLE_EQ(p.x, 0);
    const glm::dvec3 q = orbit_project({1, 0, 0}, 90, 0);
    EXPECT_NEAR(q.x, 0, 1e-15);
    EXPECT_NEAR(q.z, 1, 1e-15);
}

TEST(HomogeneousScene, BestPlaneLeavesOutTheSmallestExtent) {
    geom::Curve c;
    c.points = {{0, 0, 0}, {1, 0.1, 2}, {2, 0, 0}}; // flat in y: seen in xz
    EXPECT_EQ(best_plane(c), (std::array<int, 2>{0, 2}));
    c.points = {{0, 0, 0}, {0.1, 1, 2}, {0, 2, 0}};
    EXPECT_EQ(best_plane(c), (std::array<int, 2>{1, 2}));
    c.points = {{0, 0, 0}, {1, 1, 0.1}, {2, 0, 0}};
    EXPECT_EQ(best_plane(c), (std::array<int, 2>{0, 1}));
}
