// Which side of a closed implicit mesh the 3D view leaves unrasterized: none unless the eye,
// and everything the near clipping plane reaches, is outside the mesh's box.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "ui/view/camera.hpp"
#include "ui/view/face_culling.hpp"

using namespace isoparm::ui;

namespace {

SurfaceDraw closed_mesh(int side) {
    SurfaceDraw d;
    d.seen_side = side;
    d.box_lo = {-1, -1, -1};
    d.box_hi = {1, 1, 1};
    return d;
}

} // namespace

TEST(FaceCulling, OnlyAClosedMeshSeenFromOutsideItsBox) {
    const glm::dvec3 far_eye{0, -10, 3};
    EXPECT_EQ(hidden_faces(closed_mesh(1), far_eye, 0.1), HiddenFaces::clockwise);
    EXPECT_EQ(hidden_faces(closed_mesh(-1), far_eye, 0.1), HiddenFaces::counter_clockwise);
    EXPECT_EQ(hidden_faces(closed_mesh(0), far_eye, 0.1), HiddenFaces::none);     // open mesh
    EXPECT_EQ(hidden_faces(closed_mesh(1), {0.5, 0, 0}, 0.1), HiddenFaces::none); // inside
    EXPECT_EQ(hidden_faces(closed_mesh(1), {1, 1, 1}, 0.1), HiddenFaces::none);   // on a corner
    // Outside, but the near plane reaches into the box: the cut would show the inside.
    EXPECT_EQ(hidden_faces(closed_mesh(1), {1.05, 0, 0}, 0.1), HiddenFaces::none);
    EXPECT_EQ(hidden_faces(closed_mesh(1), {1.2, 0, 0}, 0.1), HiddenFaces::clockwise);
    // Diagonally off a corner: the distance to the box, not to a face's plane.
    EXPECT_EQ(hidden_faces(closed_mesh(1), {1.06, 1.06, 1.06}, 0.1), HiddenFaces::clockwise);
}

TEST(FaceCulling, NearPlaneReachIsTheDistanceToItsCorners) {
    Camera c;
    c.distance = 7;
    const double aspect = 1.6;
    const glm::dvec3 eye = camera_eye(c);
    const double near = glm::distance(eye, c.target) * 0.01;
    const double t = std::tan(c.fov_y / 2);
    // A corner of the near clipping rectangle, built from the camera's basis.
    const glm::dvec3 corner =
        eye + near * (camera_forward(c) + t * camera_up(c) + t * aspect * camera_right(c));
    EXPECT_NEAR(near_plane_reach(c, aspect), glm::distance(eye, corner), 1e-12);
    // And that corner is on the near plane: it projects to depth -1 at the viewport's corner.
    const glm::dvec4 clip = projection_matrix(c, aspect) * view_matrix(c) * glm::dvec4(corner, 1);
    EXPECT_NEAR(clip.z / clip.w, -1, 1e-9);
    EXPECT_NEAR(std::abs(clip.x / clip.w), 1, 1e-9);
    EXPECT_NEAR(std::abs(clip.y / clip.w), 1, 1e-9);
}
