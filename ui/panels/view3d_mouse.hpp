// The 3D view's mouse (view3d_mouse.cpp): the wheel zooms, a drag orbits (Shift, or another
// button: pans); a press on a control point selects and drags it (X/Y/Z or Shift: along an
// axis, snapped), Ctrl+drag draws a box that selects the points inside, and with many points
// selected their handle moves, turns and scales them.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <optional>

#include "ui/app_context.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/picking.hpp"
#include "ui/view/point_selection.hpp"

namespace isoparm::ui {

// A control point under the pointer, and where it is.
struct PickedPoint {
    PointRef ref;
    glm::dvec3 position;
};

// The nearest clickable control point within the pick radius of `mouse`, if any.
std::optional<PickedPoint> pick_point(const AppContext& ctx, const Viewport& vp,
                                      const glm::dvec2& mouse);
// The selection's handle where it is drawn: shown while two or more points are selected.
std::optional<HandleLayout> selection_handle(const AppContext& ctx, const Viewport& vp);
// This frame's mouse over the view's image (the last ImGui item).
void handle_mouse(AppContext& ctx, const Viewport& vp);

} // namespace isoparm::ui
