// An animated parameter's player (pure): the clock that runs a weight, a knot, the (u, v)
// indicator along a line or a circle in the domain, de Boor's step or an implicit surface's
// parameter through its range (play, pause, once, loop or bounce, speed), and the value at each
// phase. The window shows the value as a preview (core/doc/animated.hpp), never an undo step
// until the teacher keeps one.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <string>

#include "core/doc/animated.hpp"
#include "core/geom/types.hpp"

namespace isoparm::ui {

// The target (what moves and between which values) is the document's: doc::AnimationTarget.
using doc::AnimatedKind;
using doc::AnimationTarget;

using doc::describe;
using doc::indicator_at;
using doc::Repeat;
using doc::step_at;
using doc::value_at;

// The player: a phase s in [0, 1] along the range and a direction. advance(dt) moves it by
// dt * speed / seconds (one pass takes `seconds` at speed 1).
struct AnimationPlayer {
    AnimationTarget target;
    double seconds = 4; // one pass from `from` to `to` at speed 1
    double speed = 1;   // multiplies the time; 0.25 .. 4 in the panel
    Repeat repeat = Repeat::bounce;
    bool playing = false;
    double phase = 0;  // 0 at `from`, 1 at `to`
    int direction = 1; // bounce: +1 forward, -1 back

    void play(); // from the end of a finished `once` run, it starts over
    void pause() { playing = false; }
    void toggle() { playing ? pause() : play(); }
    // Moves the phase on by dt seconds of the window's clock; returns whether it changed.
    bool advance(double dt);
    // Sets the phase directly (the slider), in [0, 1].
    void seek(double phase_0_1);
};

} // namespace isoparm::ui
