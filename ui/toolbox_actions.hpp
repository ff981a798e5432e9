// The toolbox's shape changes on the current object, shared by the Surface and Curve menus,
// the curve designer and the shortcuts: knot removal, degree reduction, knot splitting and
// closing at the knot under the indicator (a surface: the tracing square's indicator; a curve:
// the curve designer's t), and type conversion after saying what it loses.
#pragma once

#include <string>

#include "core/geom/types.hpp"
#include "ui/app_context.hpp"
#include "ui/surface_actions.hpp"

namespace isoparm::ui {

enum class Tool { remove_knot, reduce_degree, split_knot, close };

// Surfaces: the selected surface in `dir`; curves: the selected curve (dir is ignored).
ActionState tool_state(const AppContext& ctx, Tool tool, geom::Dir dir, bool curve);
// Runs it through the history; what happened (or why not) goes to the status bar and the
// action note, with how far the shape moved.
void run_tool(AppContext& ctx, Tool tool, geom::Dir dir, bool curve);

// The interior knot nearest to the indicator's parameter (surfaces) or the designer's t
// (curves), if the object has one: the knot the toolbox acts on.
std::optional<double> knot_under_indicator(const AppContext& ctx, geom::Dir dir, bool curve);

// Convert to: runs at once when nothing is lost, else opens the question (draw_convert_dialog)
// that says what is lost (weights reset; the Bezier pieces a multi-span object becomes).
void request_convert(AppContext& ctx, geom::SplineType to, bool curve);
void draw_convert_dialog(AppContext& ctx);

} // namespace isoparm::ui
