// The teaching actions on the current surface at the indicator: knot insertion,
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

// Run through the history (undoable). What happened, a refusal with its reason included,
// goes to the status bar and to the tracing panel's note (current_action_note).
void insert_knot_at_indicator(AppContext& ctx, geom::Dir dir);
void elevate_current(AppContext& ctx, geom::Dir dir);
void split_at_indicator(AppContext& ctx, geom::Dir dir);

// The patch structure's continuity (a setting kept with the scene, not undoable). Switched
// to C0 or C1, the current patch group's borders that do not pair up get the knots they lack
// (conform_current_group).
void set_continuity(AppContext& ctx, doc::Continuity c);
// Inserts the knots the current group's borders lack (doc::conform_borders, shape unchanged,
// one undo step) and notes what it did; nothing when they all pair up or none can.
void conform_current_group(AppContext& ctx);

// Records the note of an action just taken (also shown in the status bar).
void note_action(AppContext& ctx, std::string text, bool refused);
// The note of the last action while nothing has changed the history since; null once the
// next edit, undo or redo made it stale.
const ActionNote* current_action_note(const AppContext& ctx);

// De Boor's step control: the last step of the current surface's construction (steps 0 ..
// p_u + p_v + 1: the u-stage's levels, then the v-stage's), and moving through them. For a
// selected triangle it is de Casteljau's instead: steps 0 .. n, step l showing level l (0 the
// control points, n the point S(r, s, t)), so the count returned is n.
int deboor_step_count(const AppContext& ctx);
void deboor_step(AppContext& ctx, int delta); // -1 back, +1 forward (from "all": restart)
void deboor_toggle_play(AppContext& ctx, double now_seconds);
// Keeps the step inside the current surface's construction: a degree, net or patch change
// can leave fewer steps than the counter had reached (it goes to the last step, S(u, v)).
// Called every frame (deboor_tick) and by the de Boor tab.
void clamp_deboor_step(AppContext& ctx);
// Frames the 3D view's camera on the (p_u + 1) x (p_v + 1) control points that act at the
// indicator, or a selected triangle's control points (the viewing angles kept; `F` frames
// everything again).
void zoom_to_acting_patch(AppContext& ctx);
// Advances a playing animation; returns whether it is still playing (the window keeps
// drawing frames while it does).
bool deboor_tick(AppContext& ctx, double now_seconds);

} // namespace isoparm::ui
