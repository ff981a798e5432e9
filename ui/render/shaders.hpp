// GLSL sources of the 3D view (GLSL 3.30 and GLSL ES 3.00 alike): lit surfaces, wide lines
// and round points.
#pragma once

namespace isoparm::ui::shaders {

// Surfaces: Blinn-Phong with two lights fixed to the camera, lit on both sides.
extern const char* const mesh_vs;
// mesh_fs needs ISOPARM_ANALYSIS defined first (the analysis kind, see mesh_fs).
extern const char* const mesh_fs;
// Lines: each segment widened to a screen-space quad (neither core profile nor WebGL has
// wide lines), clipped at the near plane first; drawn instanced, one segment an instance, four
// vertices a quad (ui/render/segments.hpp).
extern const char* const line_vs;
extern const char* const line_fs;
// Points: screen-space squares cut to disks (flat with an outline, or shaded as spheres),
// one point an instance.
extern const char* const point_vs;
extern const char* const point_fs;

} // namespace isoparm::ui::shaders
