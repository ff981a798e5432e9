// Which window frames are a gesture's (ui/gesture_frames.hpp): a drag stays one gesture between
// its mouse events, ends a quarter second after the mouse rests or at once on the release.
#include <gtest/gtest.h>

#include "ui/gesture_frames.hpp"

using isoparm::ui::GestureFrames;

TEST(GestureFrames, ADragStaysAGestureBetweenItsMouseEvents) {
    GestureFrames g;
    EXPECT_FALSE(g.step(10.0, /*held=*/true, /*moved=*/false, false)); // pressed, not moved
    EXPECT_TRUE(g.step(10.02, true, true, false));
    // Frames between two moves (the loop keeps drawing while a button is held).
    EXPECT_TRUE(g.step(10.03, true, false, false));
    EXPECT_TRUE(g.step(10.2, true, false, false));
    EXPECT_TRUE(g.step(10.21, true, true, false));
    // Held still: the full picture a quarter second after the last move.
    EXPECT_TRUE(g.step(10.45, true, false, false));
    EXPECT_FALSE(g.step(10.47, true, false, false));
}

TEST(GestureFrames, TheReleaseDrawsInFullAtOnce) {
    GestureFrames g;
    EXPECT_TRUE(g.step(1.0, true, true, false));
    EXPECT_FALSE(g.step(1.01, /*held=*/false, false, false));
    // A move without a button is no gesture (hovering).
    EXPECT_FALSE(g.step(1.02, false, true, false));
}

TEST(GestureFrames, TheWheelsZoomSettlesToo) {
    GestureFrames g;
    EXPECT_TRUE(g.step(5.0, false, false, /*wheeled=*/true));
    EXPECT_TRUE(g.step(5.1, false, false, false));
    EXPECT_FALSE(g.step(5.3, false, false, false));
}

TEST(GestureFrames, AForcedGestureIsAlwaysOne) {
    GestureFrames g;
    g.forced = true;
    EXPECT_TRUE(g.step(0.0, false, false, false));
    EXPECT_TRUE(g.step(100.0, false, false, false));
}
