// The animation player's clock and the values along a range, a segment or a circle.
#include "ui/view/animation.hpp"

#include <algorithm>
#include <cmath>

#include "core/geom/status.hpp"

namespace isoparm::ui {

void AnimationPlayer::play() {
    if (repeat == Repeat::once && phase >= 1) phase = 0;
    if (repeat == Repeat::once) direction = 1;
    playing = true;
}

bool AnimationPlayer::advance(double dt) {
    if (!playing || !(dt > 0) || !(seconds > 0) || !(speed > 0)) return false;
    const double before = phase;
    double step = dt * speed / seconds;
    switch (repeat) {
    case Repeat::once:
        phase = std::min(1.0, phase + step);
        if (phase >= 1) playing = false;
        break;
    case Repeat::loop:
        phase = std::fmod(phase + step, 1.0);
        break;
    case Repeat::bounce:
        // Reflect at the ends as often as the step crosses them (a long frame).
        step = std::fmod(step, 2.0);
        phase += direction * step;
        while (phase > 1 || phase < 0) {
            if (phase > 1) {
                phase = 2 - phase;
                direction = -1;
            } else {
                phase = -phase;
                direction = 1;
            }
        }
        break;
    }
    return phase != before;
}

void AnimationPlayer::seek(double s) {
    phase = std::isfinite(s) ? std::clamp(s, 0.0, 1.0) : 0.0;
}

} // namespace isoparm::ui
