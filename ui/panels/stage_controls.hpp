// The stage's controls inside the teaching views: the button in a view's header that puts it
// on the stage, the view under the pointer (T stages it), and a staged canvas's zoom and pan.
#pragma once

#include <string>

#include "ui/app_context.hpp"
#include "ui/view/stage.hpp"

namespace isoparm::ui {

// Whether `v` is on the stage now.
bool on_stage(const AppContext& ctx, StageView v);
// Puts `v` on the stage (none: back to the workstation); the four-view layout ends.
void set_stage(AppContext& ctx, StageView v);
// The four-view layout on or off (the stage ends).
void set_four_views(AppContext& ctx, bool on);

// The small square button with the expand mark, at the right end of the current line (or,
// with `same_line` false, at the cursor): puts `v` on the stage, or on the stage brings it
// back. Reported as stage_button/<name>.
void stage_button(AppContext& ctx, StageView v, bool same_line = true);

// `v` is the teaching view under the pointer when the current window is hovered (T stages it).
void note_hovered_view(AppContext& ctx, StageView v);

// The zoom and pan of the canvas `name` on `canvas` (the last item drawn must be its button):
// on the stage or in the four-view layout, the wheel over it zooms about the pointer, a
// right-drag begun on it pans, F returns to the fit; elsewhere the identity. The zoom is
// reported as the fact stage/zoom/<name>.
CanvasView canvas_view(AppContext& ctx, const std::string& name, const Rect& canvas);

} // namespace isoparm::ui
