// The animation player: a pass takes `seconds` at speed 1, once stops, loop wraps, bounce
// reflects; values along a range, a segment and a circle, and de Boor's steps.
#include <gtest/gtest.h>

#include "ui/view/animation.hpp"

using namespace isoparm::ui;

namespace {

TEST(Animation, OnceStopsAtTheEndAndStartsOverWhenPlayedAgain) {
    AnimationPlayer p;
    p.target.from = 0;
    p.target.to = 5;
    p.seconds = 2;
    p.repeat = Repeat::once;
    EXPECT_FALSE(p.advance(0.5)) << "paused: nothing moves";
    p.play();
    EXPECT_TRUE(p.advance(0.5));
    EXPECT_DOUBLE_EQ(p.phase, 0.25);
    EXPECT_DOUBLE_EQ(value_at(p.target, p.phase), 1.25);
    p.speed = 2;
    p.advance(1);
    EXPECT_EQ(p.phase, 1);
    EXPECT_FALSE(p.playing);
    EXPECT_EQ(value_at(p.target, p.phase), 5) << "exactly `to` at the end";
    p.play();
    EXPECT_EQ(p.phase, 0);
}

TEST(Animation, LoopWrapsAndBounceReflects) {
    AnimationPlayer p;
    p.seconds = 1;
    p.repeat = Repeat::loop;
    p.play();
    p.advance(0.75);
    p.advance(0.5);
    EXPECT_NEAR(p.phase, 0.25, 1e-12);
    AnimationPlayer b;
    b.seconds = 1;
    b.repeat = Repeat::bounce;
    b.play();
    b.advance(0.75);
    b.advance(0.5); // 1.25 -> reflected to 0.75, going back
    EXPECT_NEAR(b.phase, 0.75, 1e-12);
    EXPECT_EQ(b.direction, -1);
    b.advance(1.0); // 0.75 - 1 = -0.25 -> 0.25, forward again
    EXPECT_NEAR(b.phase, 0.25, 1e-12);
    EXPECT_EQ(b.direction, 1);
    b.advance(100.3); // a very long frame stays inside [0, 1]
    EXPECT_GE(b.phase, 0);
    EXPECT_LE(b.phase, 1);
    b.pause();
    const double at = b.phase;
    b.advance(1);
    EXPECT_EQ(b.phase, at);
    b.seek(2);
    EXPECT_EQ(b.phase, 1);
}

TEST(Animation, IndicatorAlongALineAndAroundACircle) {
    AnimationTarget t;
    t.kind = AnimatedKind::indicator_line;
    t.uv_from = {0.1, 0.2};
    t.uv_to = {0.9, 0.6};
    EXPECT_EQ(indicator_at(t, 0), glm::dvec2(0.1, 0.2));
    EXPECT_EQ(indicator_at(t, 1), glm::dvec2(0.9, 0.6));
    EXPECT_NEAR(indicator_at(t, 0.5).x, 0.5, 1e-15);
    t.kind = AnimatedKind::indicator_circle;
    t.centre = {0.5, 0.5};
    t.radius = 0.25;
    EXPECT_NEAR(indicator_at(t, 0).x, 0.75, 1e-15);
    EXPECT_NEAR(indicator_at(t, 0.25).y, 0.75, 1e-15);
    t.radius = 0.8; // leaves the square: clamped to it
    const glm::dvec2 q = indicator_at(t, 0.5);
    EXPECT_EQ(q.x, 0);
}

TEST(Animation, DeBoorStepsShareThePhaseEqually) {
    AnimationTarget t;
    t.kind = AnimatedKind::deboor_step;
    t.from = 0;
    t.to = 3; // steps 0, 1, 2, 3: a quarter each
    EXPECT_EQ(step_at(t, 0), 0);
    EXPECT_EQ(step_at(t, 0.24), 0);
    EXPECT_EQ(step_at(t, 0.26), 1);
    EXPECT_EQ(step_at(t, 0.74), 2);
    EXPECT_EQ(step_at(t, 0.99), 3);
    EXPECT_EQ(step_at(t, 1), 3);
}

TEST(Animation, DescribesWhatMoves) {
    AnimationTarget t;
    t.kind = AnimatedKind::weight;
    t.i = 2;
    t.j = 3;
    t.from = 0;
    t.to = 5;
    EXPECT_EQ(describe(t), "w23 from 0 to 5");
    t.kind = AnimatedKind::knot;
    t.k = 4;
    t.from = 0.25;
    t.to = 0.5;
    EXPECT_EQ(describe(t), "knot u4 from 0.25 to 0.5");
}

} // namespace
