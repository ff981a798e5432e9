// The Surface menu's actions on triangular Bezier patches: a new patch, degree elevation and
// the split at the triangle's indicator (r, s, t), each one undo step.
#pragma once

#include "ui/app_context.hpp"
#include "ui/surface_actions.hpp"

namespace isoparm::ui {

// Adds a flat triangle of this degree (doc::make_flat_triangle) beside the scene and selects
// it with its middle control point.
void new_triangle(AppContext& ctx, int degree, bool rational);

// For the selected triangle (disabled with the reason otherwise).
ActionState elevate_triangle_state(const AppContext& ctx);
ActionState split_triangle_state(const AppContext& ctx);
void elevate_selected_triangle(AppContext& ctx);
void split_triangle_at_indicator(AppContext& ctx);

} // namespace isoparm::ui
