// Trimming in the window: a loop drawn corner by corner in the tracing square, a round hole cut
// at the indicator, and removing a surface's trim; shared by the Surface menu, the tracing
// panel and the keyboard (the loops themselves: core/geom/trim).
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <vector>

#include "core/geom/trim/trim.hpp"

#include "ui/app_context.hpp"
#include "ui/surface_actions.hpp"

namespace isoparm::ui {

// The hole's radius as a fraction of the current surface's shorter domain side.
inline constexpr double punched_hole_radius = 0.1;

// Enabled exactly when the command would apply (the command's own refusal is the reason).
ActionState punch_hole_state(const AppContext& ctx);
ActionState remove_trim_state(const AppContext& ctx);

// Run through the history (undoable); the outcome goes to the status bar and the tracing
// panel's note.
void punch_hole_at_indicator(AppContext& ctx);
void remove_trim_current(AppContext& ctx);

// Drawing a loop (ctx.ui.trim_drawing): started from the menu on the current surface, corners
// added by clicks in the tracing square (in the surface's own (u, v)), closed by Enter or a
// click on the first corner, the last corner taken back by Backspace, abandoned by Escape. The
// closed polygon is turned to run the right way (holes clockwise, the outer loop
// counter-clockwise) and set as one undo step; a refusal (a loop crossing another, leaving the
// domain) keeps the corners so that the drawing can be mended.
ActionState draw_hole_state(const AppContext& ctx);
ActionState draw_outer_state(const AppContext& ctx);
void start_drawing_hole(AppContext& ctx);
void start_drawing_outer(AppContext& ctx);
void add_loop_corner(AppContext& ctx, glm::dvec2 uv);
void take_back_loop_corner(AppContext& ctx);
void close_drawn_loop(AppContext& ctx);
void cancel_loop_drawing(AppContext& ctx);
// The loop the corners make: the polygon through them, or (smooth) the closed cubic B-spline
// they are the control points of (geom::polygon_loop, geom::smooth_loop). Which one a drawing
// makes is ctx.ui.smooth_loops, switched from the menu or by C while drawing.
geom::TrimLoop drawn_loop(const std::vector<glm::dvec2>& corners, bool smooth);
void toggle_smooth_loops(AppContext& ctx);

// Trimming by a closed curve drawn in the curve designer in the xy, xz or yz plane: its
// projection along the plane's normal onto the current surface (core/geom/trim/projected_loop)
// becomes one more hole, or the outer loop. The item is enabled for a curve in a plane; the
// projection's refusal (not closed, missing the surface) is the action's note.
ActionState trim_by_curve_state(const AppContext& ctx, const doc::Object& curve);
void trim_by_curve(AppContext& ctx, std::uint64_t curve, bool hole);

} // namespace isoparm::ui
