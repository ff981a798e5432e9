// GLSL 3.30 sources of the 3D view: lit surfaces, wide lines and round points.
#pragma once

namespace isoparm::ui::shaders {

// Surfaces: Blinn-Phong with two lights fixed to the camera, lit on both sides.
extern const char* const mesh_vs;
extern const char* const mesh_fs;
// Lines: each segment widened to a screen-space quad in a geometry shader (core profile
// has no wide lines), clipped at the near plane first.
extern const char* const line_vs;
extern const char* const line_gs;
extern const char* const line_fs;
// Points: screen-space squares cut to disks (flat with an outline, or shaded as spheres).
extern const char* const point_vs;
extern const char* const point_gs;
extern const char* const point_fs;

} // namespace isoparm::ui::shaders
