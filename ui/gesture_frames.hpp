// Which frames of the window are a gesture's (a drag, an orbit, the wheel's zoom), drawn coarse
// on a CPU rasteriser: the workstation's policy, without ImGui, so that it can be tested.
#pragma once

namespace isoparm::ui {

// Gesture frames on a CPU rasteriser (llvmpipe): while the mouse drags (a point, the indicator,
// an orbit) or the wheel turns, the implicit objects are drawn from meshes of a coarse grid
// (2.5 cells or more: a sixth of the triangles; a software rasteriser's orbit of the implicit
// gallery is bound by triangles, not pixels) and the untrimmed surfaces from at most 8 samples a
// span (tessellation_sampling.hpp: small triangles cost llvmpipe their edges' blocks over again);
// the frame a quarter second after the mouse's last move, and the one after the release, is drawn
// in full. Headless renders are never gestures. (Half-resolution gesture frames were measured and
// dropped: llvmpipe's scaled blit cost more than the fill they saved.)
struct GestureFrames {
    bool coarse = true;  // draw gestures coarse (off: every frame in full, as before)
    bool forced = false; // a gesture without the mouse (the frame benchmark's drags)
    bool active = false; // the last frame was drawn coarse
    // A gesture lasts this long past the mouse's last move (the button still held) or the
    // wheel's last turn: the frames between two mouse events of one drag stay coarse instead
    // of each drawing in full and remaking every surface's mesh twice.
    static constexpr double settle_seconds = 0.25;
    double last_move = -1e9, last_wheel = -1e9; // the times of each, in seconds

    // Whether the frame at `now` (seconds) is a gesture's: the mouse `held` down and `moved`
    // this frame, the wheel `wheeled`, or either within settle_seconds before (the button
    // still held for a drag).
    bool step(double now, bool held, bool moved, bool wheeled) {
        if (forced) return true;
        if (held && moved) last_move = now;
        if (wheeled) last_wheel = now;
        return (held && now - last_move < settle_seconds) || now - last_wheel < settle_seconds;
    }
};

} // namespace isoparm::ui
