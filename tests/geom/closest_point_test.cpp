// Point inversion against shapes whose nearest points are known in closed form.
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geom/closest_point.hpp"
#include "core/geom/construct.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "tests/support/small_surfaces.hpp"

namespace isoparm::geom {
namespace {

TEST(ClosestPoint, CircleFromOutsideAndInside) {
    const Curve circle = *full_circle({0, 0, 0}, 2.0, Plane::xy);
    for (double degrees : {0.0, 37.0, 95.0, 181.0, 300.0}) {
        const double a = degrees * M_PI / 180;
        const glm::dvec3 dir{std::cos(a), std::sin(a), 0};
        for (double r : {0.5, 3.5}) {
            const auto foot = closest_point(circle, r * dir);
            ASSERT_TRUE(foot);
            EXPECT_NEAR(foot->distance, std::abs(r - 2.0), 1e-12) << degrees << " " << r;
            EXPECT_NEAR(glm::length(foot->point - 2.0 * dir), 0, 1e-9) << degrees;
        }
    }
}

TEST(ClosestPoint, CurveEndClampsToTheDomain) {
    const Curve line = line_segment({0, 0, 0}, {1, 0, 0});
    const auto foot = closest_point(line, {3, 4, 0});
    ASSERT_TRUE(foot);
    EXPECT_DOUBLE_EQ(foot->t, domain(line).hi);
    EXPECT_NEAR(foot->distance, std::hypot(2.0, 4.0), 1e-12);
}

TEST(ClosestPoint, PlaneFootIsTheOrthogonalProjection) {
    const Surface plane = testing::bilinear_patch(1, 1, 1, 1); // the unit square, z = 0
    const auto foot = closest_point(plane, {0.3, 0.6, 2.0});
    ASSERT_TRUE(foot);
    EXPECT_NEAR(foot->distance, 2.0, 1e-12);
    EXPECT_NEAR(foot->u, 0.3, 1e-12);
    EXPECT_NEAR(foot->v, 0.6, 1e-12);
    // Outside the square: the nearest point is on its edge.
    const auto edge = closest_point(plane, {1.5, 0.5, 0.0});
    ASSERT_TRUE(edge);
    EXPECT_NEAR(edge->distance, 0.5, 1e-12);
}

TEST(ClosestPoint, SphereOfRevolutionAndPointsOnIt) {
    // A half circle in xz revolved about z: the unit sphere, a NURBS with weights below 1.
    const Curve half = *circular_arc({0, 0, 0}, 1.0, -90, 90, Plane::xz);
    const Surface sphere = *revolve(half, 360);
    for (const glm::dvec3 p : {glm::dvec3(2, 1, 0.5), glm::dvec3(0.1, -0.3, 0.2),
                               glm::dvec3(-1, -1, -1), glm::dvec3(0.3, 0.2, 3)}) {
        const auto foot = closest_point(sphere, p);
        ASSERT_TRUE(foot);
        EXPECT_NEAR(foot->distance, std::abs(glm::length(p) - 1.0), 1e-9) << p.x;
    }
    // A point of the surface itself is found at distance ~0.
    for (double u : {0.1, 0.45, 0.8})
        for (double v : {0.05, 0.5, 0.93}) {
            const ParamRect d = domain(sphere);
            const glm::dvec3 on = *surface_point(sphere, d.u.lo + u * (d.u.hi - d.u.lo),
                                                 d.v.lo + v * (d.v.hi - d.v.lo));
            const auto foot = closest_point(sphere, on);
            ASSERT_TRUE(foot);
            EXPECT_LT(foot->distance, 1e-12);
        }
}

} // namespace
} // namespace isoparm::geom
