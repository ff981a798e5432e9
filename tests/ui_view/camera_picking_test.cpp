// Camera maths and picking: projection, rays, drags in the view plane and along axes.
#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "ui/view/camera.hpp"
#include "ui/view/picking.hpp"

using namespace isoparm::ui;

namespace {
const Viewport vp{100, 50, 800, 600};
} // namespace

TEST(Camera, TargetProjectsToTheViewportCentre) {
    Camera c;
    c.target = {1, 2, 3};
    const Projected p = project(view_projection(c, vp.aspect()), vp, c.target);
    ASSERT_TRUE(p.visible);
    EXPECT_NEAR(p.pixel.x, 500, 1e-6);
    EXPECT_NEAR(p.pixel.y, 350, 1e-6);
}

TEST(Camera, BasisIsOrthonormalAndZUp) {
    Camera c;
    c.yaw = 0.3;
    c.pitch = 0.4;
    EXPECT_NEAR(glm::dot(camera_right(c), camera_up(c)), 0, 1e-12);
    EXPECT_NEAR(glm::dot(camera_right(c), camera_forward(c)), 0, 1e-12);
    EXPECT_NEAR(glm::length(camera_up(c)), 1, 1e-12);
    EXPECT_GT(camera_up(c).z, 0);
    EXPECT_NEAR(glm::length(camera_eye(c) - c.target), c.distance, 1e-12);
}

TEST(Camera, PointsAboveTheTargetAppearHigherOnScreen) {
    Camera c;
    const glm::dmat4 m = view_projection(c, vp.aspect());
    EXPECT_LT(project(m, vp, {0, 0, 1}).pixel.y, project(m, vp, {0, 0, 0}).pixel.y);
    EXPECT_GT(project(m, vp, camera_right(c)).pixel.x, project(m, vp, {0, 0, 0}).pixel.x);
}

TEST(Camera, BehindTheEyeIsNotVisible) {
    Camera c;
    const glm::dvec3 behind = camera_eye(c) - camera_forward(c) * 2.0;
    EXPECT_FALSE(project(view_projection(c, vp.aspect()), vp, behind).visible);
}

TEST(Camera, PixelRayPassesThroughTheProjectedPoint) {
    Camera c;
    c.yaw = 1.1;
    const glm::dvec3 p{0.4, -0.7, 0.9};
    const Projected pr = project(view_projection(c, vp.aspect()), vp, p);
    const Ray r = pixel_ray(c, vp, pr.pixel);
    const glm::dvec3 to_p = p - r.origin;
    const double along = glm::dot(to_p, r.dir);
    EXPECT_NEAR(glm::length(to_p - along * r.dir), 0, 1e-9);
}

TEST(Camera, OrbitClampsPitchAndPanMovesTarget) {
    Camera c;
    orbit(c, 0, 1e6);
    EXPECT_LT(c.pitch, 1.5708);
    Camera d;
    const glm::dvec3 before = d.target;
    pan(d, 100, 0, 600);
    EXPECT_LT(glm::dot(d.target - before, camera_right(d)), 0); // content follows the mouse
    zoom(d, 0.5);
    EXPECT_NEAR(d.distance, Camera{}.distance * 0.5, 1e-12);
}

TEST(Camera, PanKeepsThePointUnderTheMouse) {
    Camera c;
    const glm::dvec3 p = c.target;
    const Projected before = project(view_projection(c, vp.aspect()), vp, p);
    pan(c, 40, -25, vp.h);
    const Projected after = project(view_projection(c, vp.aspect()), vp, p);
    EXPECT_NEAR(after.pixel.x - before.pixel.x, 40, 1e-6);
    EXPECT_NEAR(after.pixel.y - before.pixel.y, -25, 1e-6);
}

TEST(Camera, FitShowsEveryPointAndFillsTheView) {
    const std::vector<std::vector<glm::dvec3>> sets = {
        {{-3, -1, 0}, {5, 2, 1}, {5, -1, 0}, {-3, 2, 1}},           // a flat slab
        {{0, 0, 0}, {0, 0, 10}},                                    // a tall thin segment
        {{1, 1, 1}, {1.5, 0.2, -3}, {-2, 4, 0.5}, {0.3, 0.3, 0.3}}, // scattered
    };
    for (const auto& pts : sets) {
        Camera c;
        fit_to_points(c, pts, vp.aspect());
        const glm::dmat4 m = view_projection(c, vp.aspect());
        glm::dvec2 lo(1e9), hi(-1e9);
        for (const glm::dvec3& q : pts) {
            const Projected p = project(m, vp, q);
            ASSERT_TRUE(p.visible);
            EXPECT_GE(p.pixel.x, vp.x);
            EXPECT_LE(p.pixel.x, vp.x + vp.w);
            EXPECT_GE(p.pixel.y, vp.y);
            EXPECT_LE(p.pixel.y, vp.y + vp.h);
            lo = glm::min(lo, p.pixel);
            hi = glm::max(hi, p.pixel);
        }
        // Filled: the points span at least 80% of the width or of the height, centred.
        EXPECT_TRUE(hi.x - lo.x >= 0.8 * vp.w || hi.y - lo.y >= 0.8 * vp.h);
        EXPECT_NEAR((lo.x + hi.x) / 2, vp.x + vp.w / 2, 0.05 * vp.w);
        EXPECT_NEAR((lo.y + hi.y) / 2, vp.y + vp.h / 2, 0.05 * vp.h);
    }
}

TEST(Drag, ViewPlaneDragFollowsTheMouseAtTheSameDepth) {
    Camera c;
    const glm::dvec3 start{0.5, 0.2, 0.1};
    const glm::dmat4 m = view_projection(c, vp.aspect());
    const glm::dvec2 target = project(m, vp, start).pixel + glm::dvec2(30, -20);
    const glm::dvec3 moved = drag_in_view_plane(c, vp, start, target);
    EXPECT_NEAR(glm::dot(moved - start, camera_forward(c)), 0, 1e-9); // stays in the plane
    const glm::dvec2 back = project(m, vp, moved).pixel;
    EXPECT_NEAR(back.x, target.x, 1e-6);
    EXPECT_NEAR(back.y, target.y, 1e-6);
}

TEST(Drag, AxisDragMovesOnlyThatCoordinate) {
    Camera c;
    const glm::dvec3 start{0.5, 0.2, 0.1};
    const glm::dmat4 m = view_projection(c, vp.aspect());
    const glm::dvec2 mouse = project(m, vp, start).pixel + glm::dvec2(10, -60);
    for (int axis = 0; axis < 3; ++axis) {
        const glm::dvec3 moved = drag_along_axis(c, vp, start, axis, mouse);
        for (int other = 0; other < 3; ++other) {
            if (other != axis) {
                EXPECT_DOUBLE_EQ(moved[other], start[other]);
            }
        }
    }
    // Straight up on screen from a camera above the xy-plane is mostly z.
    EXPECT_EQ(dominant_axis(c, vp, start, {0, -50}), 2);
}

TEST(Drag, ClosestOnLineIsUndefinedWhenParallel) {
    const Ray r{{0, 0, 0}, {1, 0, 0}};
    EXPECT_FALSE(closest_on_line(r, {0, 1, 0}, {1, 0, 0}).has_value());
    const auto p = closest_on_line(r, {2, 1, 5}, {0, 0, 1});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->z, 0, 1e-12);
    EXPECT_NEAR(p->x, 2, 1e-12);
}

TEST(Picking, NearestWithinRadiusOnly) {
    std::vector<Projected> pts(3);
    pts[0] = {{100, 100}, 0.5, true};
    pts[1] = {{110, 100}, 0.5, true};
    pts[2] = {{300, 300}, 0.5, true};
    EXPECT_EQ(pick_nearest(pts, {108, 101}, 10), 1u);
    EXPECT_EQ(pick_nearest(pts, {101, 100}, 10), 0u);
    EXPECT_FALSE(pick_nearest(pts, {200, 200}, 10).has_value());
}

TEST(Picking, InvisiblePointsAreSkippedAndTiesGoToTheNearerPoint) {
    std::vector<Projected> pts(3);
    pts[0] = {{100, 100}, -0.2, false}; // behind the eye
    pts[1] = {{100, 100}, 0.9, true};
    pts[2] = {{100.2, 100}, 0.1, true}; // practically the same pixel, nearer the eye
    EXPECT_EQ(pick_nearest(pts, {100, 100}, 5), 2u);
    pts[2].visible = false;
    EXPECT_EQ(pick_nearest(pts, {100, 100}, 5), 1u);
}
