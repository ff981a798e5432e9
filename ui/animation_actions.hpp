// The animated parameter in the window: start one on a target, run it on the window's clock
// showing its value as a preview (core/doc/animated.hpp) from the start of a frame to its end,
// stop it (the document back bit for bit), or keep the value shown (one undo step).
#pragma once

#include <string>

#include "core/doc/animated.hpp"
#include "ui/app_context.hpp"

namespace isoparm::ui {

// Puts `target` on the Animate slider (the Animate panel opens); refused targets leave the
// reason in the panel and the status bar. Returns whether it started.
bool start_animation(AppContext& ctx, const doc::AnimationTarget& target, double seconds,
                     doc::Repeat repeat, bool play);
// Ends the animation: nothing shown any more, the document as it was.
void stop_animation(AppContext& ctx);
// Keeps the value shown: the document back as it was, then the one command that sets the
// value (set_weight, move_knot, an implicit's edit), one undo step; the animation pauses.
void keep_animation_value(AppContext& ctx);

// The frame's part: at its start the clock advances and the value is shown on the document;
// at its end the document is put back (so saving, autosave and every command see it as it
// is). Returns whether frames must keep coming (it plays).
bool animation_begin_frame(AppContext& ctx, double now_seconds);
void animation_end_frame(AppContext& ctx);
// Before a command or a save inside the frame: the preview taken back and the player paused
// (a person's edit wins over the animation).
void suspend_animation(AppContext& ctx);

// A target for the selected control point's weight, from 0 to 5 (or its own value to 5).
doc::AnimationTarget weight_target_of_selection(const doc::Document& doc);

} // namespace isoparm::ui
