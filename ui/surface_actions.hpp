// The teaching actions on the current surface at the indicator (issue 5): knot insertion,
// degree elevation and splitting, shared by the Surface menu and the keyboard shortcuts.
#pragma once

#include <string>

#include "core/geom/types.hpp"
#include "ui/app_context.hpp"

namespace isoparm::ui {

// What an action would do right now, for the menu: its label (with the parameter) and
// whether it can run (if not, `why` says why, for the tooltip).
struct ActionState {
    std::string label;
    bool enabled = false;
    std::string why;
};
ActionState insert_knot_state(const AppContext& ctx, geom::Dir dir);
ActionState elevate_state(const AppContext& ctx, geom::Dir dir);
ActionState split_state(const AppContext& ctx, geom::Dir dir);

// Run through the history (undoable); a refusal shows in the status bar.
void insert_knot_at_indicator(AppContext& ctx, geom::Dir dir);
void elevate_current(AppContext& ctx, geom::Dir dir);
void split_at_indicator(AppContext& ctx, geom::Dir dir);

// De Boor's step control: the number of steps of the current surface's construction (the
// u-stage's levels, then the v-stage's), and moving through them.
int deboor_step_count(const AppContext& ctx);
void deboor_step(AppContext& ctx, int delta); // -1 back, +1 forward (from "all": restart)
void deboor_toggle_play(AppContext& ctx, double now_seconds);
// Advances a playing animation; returns whether it is still playing (the window keeps
// drawing frames while it does).
bool deboor_tick(AppContext& ctx, double now_seconds);

} // namespace isoparm::ui
