// The grid the 3D view draws an implicit surface at (ui/view/implicit_screen_level.hpp): coarser
// as the object recedes, never coarser than its cell would look at screen_cell_pixels, and
// the object's own cell when the eye is inside its box or the scale is unknown.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "ui/view/camera.hpp"
#include "ui/view/implicit_screen_level.hpp"

using namespace isoparm::ui;

namespace {

// A cube of edge 2 whose nearest face is `distance` from an eye at the origin.
int level_at(double distance, double cell, double pixels_at_unit_distance) {
    ScreenScale s;
    s.pixels_at_unit_distance = pixels_at_unit_distance;
    return screen_level({distance, -1, -1}, {distance + 2, 1, 1}, cell, s);
}

} // namespace

TEST(ImplicitScreenLevel, CoarserAsTheObjectRecedesUpToTheLastLevel) {
    // A cell of 0.01 at 1000 px per unit at distance 1 looks 10 / distance pixels.
    EXPECT_EQ(level_at(1, 0.01, 1000), 0);    // 10 px
    EXPECT_EQ(level_at(4.9, 0.01, 1000), 0);  // 2.04 px: twice that is over 4
    EXPECT_EQ(level_at(5.1, 0.01, 1000), 1);  // 1.96 px: drawn at 3.9 px
    EXPECT_EQ(level_at(9.9, 0.01, 1000), 1);  // 1.01 px: four times is over 4
    EXPECT_EQ(level_at(10.1, 0.01, 1000), 2); // 0.99 px: drawn at 3.96 px
    EXPECT_EQ(level_at(1000, 0.01, 1000), max_screen_level);
}

TEST(ImplicitScreenLevel, TheOwnCellWhereTheScaleOrTheCellIsUnknown) {
    ScreenScale inside;
    inside.pixels_at_unit_distance = 1;
    inside.eye = {0.5, 0.5, 0.5};
    EXPECT_EQ(screen_level({0, 0, 0}, {1, 1, 1}, 0.01, inside), 0); // the eye in the box
    EXPECT_EQ(level_at(100, 0.01, 0), 0);
    EXPECT_EQ(level_at(100, 0.01, -5), 0);
    EXPECT_EQ(level_at(100, 0.01, std::numeric_limits<double>::quiet_NaN()), 0);
    EXPECT_EQ(level_at(100, 0, 1000), 0);
    EXPECT_EQ(level_at(100, std::numeric_limits<double>::quiet_NaN(), 1000), 0);
}

// The scale agrees with the camera's own projection: a cell across the line of sight at the
// target projects to cell * pixels_at_unit_distance / distance pixels.
TEST(ImplicitScreenLevel, TheScaleIsTheCamerasProjection) {
    Camera c;
    c.target = {1, 2, 3};
    c.distance = 8;
    const Viewport vp{0, 0, 900, 600};
    const ScreenScale s = screen_scale(c, 600);
    EXPECT_NEAR(glm::distance(s.eye, camera_eye(c)), 0, 1e-12);
    const glm::dmat4 m = view_projection(c, 900.0 / 600.0);
    const double cell = 0.05;
    const glm::dvec3 across = camera_right(c) * cell;
    const double pixels = glm::distance(project(m, vp, c.target - across / 2.0).pixel,
                                        project(m, vp, c.target + across / 2.0).pixel);
    EXPECT_NEAR(pixels, cell * s.pixels_at_unit_distance / c.distance, 1e-9 * pixels);
    EXPECT_EQ(screen_scale(c, 0).pixels_at_unit_distance, 0);
}
