// How fine an implicit object's mesh has to be for the 3D view. Marching cubes makes about two
// triangles per cell the surface crosses, so a cell that projects under a pixel or two fills the
// picture with triangles smaller than its pixels: a software rasterizer pays for each of them
// (the implicit gallery at 1280 x 800: 880,000 triangles, several to a pixel, 0.26 s of
// llvmpipe's time) and the picture gains nothing. The 3D view draws a mesh of a coarser grid
// instead, the object's cell times 2^level, as long as that cell still projects to at most a few
// pixels.
#pragma once

#include <glm/vec3.hpp>

#include "ui/view/camera.hpp"

namespace isoparm::ui {

// The coarsest a drawn cell may look, in pixels, where the object comes nearest the eye. At 4,
// a surface of curvature radius R pixels on screen is off its polygon by at most about
// 4^2 / (8 R) pixels (a sphere 40 pixels across: 0.1 px); normals come from f's gradient, so the
// shading does not coarsen. What does change is what a grid cannot resolve: seams where a
// surface passes through itself and cusps move by a pixel or two (the implicit gallery at
// 1280 x 800, every object at twice its cell: 663 of its 1,024,000 pixels differ by more
// than 8 of 255).
constexpr double screen_cell_pixels = 4.0;
// At most 4x the cell: a coarser grid starts to lose the thin parts a finer cell was chosen
// for (the seams where the Roman surface passes through itself).
constexpr int max_screen_level = 2;

struct ScreenScale {
    glm::dvec3 eye{0.0};
    double pixels_at_unit_distance = 0; // the pixels one unit spans at distance 1 from the eye
};
// The scale of a perspective view `height_px` pixels high.
ScreenScale screen_scale(const Camera& camera, int height_px);

// 0 (the object's own cell) .. max_screen_level: the largest level whose cell, cell * 2^level,
// projects to at most screen_cell_pixels at the point of the box [lo, hi] nearest the eye.
// 0 when the eye is in the box, the scale is unknown (not positive) or the cell is not.
int screen_level(const glm::dvec3& lo, const glm::dvec3& hi, double cell, const ScreenScale& s);

} // namespace isoparm::ui
