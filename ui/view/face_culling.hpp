// Which side of a surface's triangles the 3D view may leave unrasterized. On a software
// rasterizer a fine implicit mesh costs per triangle, and half of a closed mesh faces away.
#pragma once

#include <glm/vec3.hpp>

#include "ui/view/scene_draw.hpp"

namespace isoparm::ui {

enum class HiddenFaces { none, clockwise, counter_clockwise }; // as the eye sees them

// A closed mesh inside its box (d.seen_side != 0) shows only its seen side to an eye outside
// the box: a line of sight enters the box outside the mesh and meets it first from there
// (geom::implicit::side_seen_from_outside). The other side is hidden unless the near clipping
// plane, which reaches `near_reach` from the eye, cuts into the box and opens the inside.
HiddenFaces hidden_faces(const SurfaceDraw& d, const glm::dvec3& eye, double near_reach);

} // namespace isoparm::ui
