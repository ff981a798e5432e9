// Issue 5 in the workstation: de Boor's step control and overlay, the actions at the
// indicator (insert, elevate, split) and the indicator over a patch group's shared domain.
#include <gtest/gtest.h>

#include "core/doc/patches.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/knots.hpp"
#include "ui/app_context.hpp"
#include "ui/deboor_overlay.hpp"
#include "ui/doc_access.hpp"
#include "ui/scene_builder.hpp"
#include "ui/surface_actions.hpp"

using namespace isoparm;
using namespace isoparm::ui;
using geom::Dir;

namespace {

AppContext hill_context() {
    AppContext ctx;
    ctx.doc = doc::default_document(); // bicubic 5x5 NURBS
    ctx.doc.selection = {ctx.doc.objects[0].id, -1, -1};
    return ctx;
}

TEST(DeBoorSteps, ULevelsThenVLevelsThenThePoint) {
    EXPECT_EQ(deboor_step_info(0, 3, 2).level, 0);
    EXPECT_TRUE(deboor_step_info(2, 3, 2).u_stage);
    EXPECT_EQ(deboor_step_info(2, 3, 2).level, 2);
    EXPECT_FALSE(deboor_step_info(4, 3, 2).u_stage); // the column polygon
    EXPECT_EQ(deboor_step_info(4, 3, 2).level, 0);
    EXPECT_EQ(deboor_step_info(6, 3, 2).level, 2);
    EXPECT_NE(deboor_step_info(6, 3, 2).text.find("S(u, v)"), std::string::npos);
}

TEST(DeBoorSteps, StepBackAndForthAndPlayToTheEnd) {
    AppContext ctx = hill_context();
    EXPECT_EQ(deboor_step_count(ctx), 7); // 3 + 3 + 1
    deboor_step(ctx, +1);                 // from "all": the first step
    EXPECT_EQ(ctx.ui.deboor.step, 0);
    EXPECT_TRUE(ctx.doc.display.deboor);
    deboor_step(ctx, +1);
    deboor_step(ctx, +1);
    deboor_step(ctx, -1);
    EXPECT_EQ(ctx.ui.deboor.step, 1);
    deboor_step(ctx, -5);
    EXPECT_EQ(ctx.ui.deboor.step, 0);
    deboor_toggle_play(ctx, 10.0);
    EXPECT_TRUE(ctx.ui.deboor.playing);
    double t = 10.0;
    int ticks = 0;
    while (deboor_tick(ctx, t += 1.0)) ++ticks;
    EXPECT_EQ(ctx.ui.deboor.step, 7);
    EXPECT_EQ(ticks, 6); // the seventh step ends the play
}

std::size_t count_points(const Overlay& o, float size_over_scale, float scale = 1) {
    std::size_t n = 0;
    for (const PointBatch& b : o.points)
        if (b.size_px == size_over_scale * scale) n += b.points.size();
    return n;
}

TEST(DeBoorOverlay, StepZeroRingsTheActivePointsAndTheEndShowsSuv) {
    const doc::Document d = doc::default_document();
    const geom::Surface& s = std::get<doc::SurfaceObject>(d.objects[0].shape).surface;
    const geom::DeBoorSurfaceTrace trace = geom::deboor_surface(s, 0.3, 0.6);
    Overlay first;
    add_deboor_overlay(trace, 3, 3, 0, 1, first);
    EXPECT_EQ(count_points(first, 8), 16u); // (p_u + 1) x (p_v + 1)
    EXPECT_TRUE(first.lines.empty());
    EXPECT_EQ(count_points(first, 16), 0u);

    Overlay all;
    add_deboor_overlay(trace, 3, 3, -1, 1, all);
    ASSERT_EQ(count_points(all, 16), 1u); // the red sphere S(u, v)
    const glm::vec3 p = all.points.back().points[0].position;
    const auto expected = trace.point();
    ASSERT_TRUE(expected);
    EXPECT_NEAR(p.x, expected->x, 1e-6);
    EXPECT_NEAR(p.z, expected->z, 1e-6);
    // Every row's three u levels (3 + 2 + 1 points) and the v-stage's: many more points.
    EXPECT_GT(count_points(all, 8), 16u + 5 * 6);
}

TEST(DeBoorOverlay, SceneBuilderFollowsTheDisplayFlagAndTheStep) {
    doc::Document d = doc::default_document();
    d.selection = {d.objects[0].id, -1, -1};
    SceneStyle style;
    const std::size_t without = build_scene(d, style).overlay.points.size();
    d.display.deboor = true;
    style.deboor_step = 0;
    const BuiltScene some = build_scene(d, style);
    style.deboor_step = -1;
    const BuiltScene all = build_scene(d, style);
    EXPECT_GT(some.overlay.points.size(), without);
    EXPECT_GT(all.overlay.points.size(), some.overlay.points.size());
}

TEST(SurfaceActions, InsertUpToTheDegreeThenRefuseShapeUnchanged) {
    AppContext ctx = hill_context();
    ctx.doc.indicator = {0.25, 0.5};
    const geom::Surface before = std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface;
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(insert_knot_state(ctx, Dir::u).enabled) << k;
        insert_knot_at_indicator(ctx, Dir::u);
    }
    const geom::Surface& after = std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface;
    EXPECT_EQ(geom::multiplicity(after.knots_u, 0.25), 3);
    EXPECT_EQ(after.n_u, before.n_u + 3);
    const ActionState full = insert_knot_state(ctx, Dir::u);
    EXPECT_FALSE(full.enabled);
    EXPECT_NE(full.why.find("multiplicity 3"), std::string::npos) << full.why;
    EXPECT_EQ(ctx.history.size(), 3u); // three undo steps, one per insertion
    ctx.history.undo(ctx.doc);
    ctx.history.undo(ctx.doc);
    ctx.history.undo(ctx.doc);
    EXPECT_EQ(std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface.points, before.points);
}

TEST(SurfaceActions, ElevateAndSplitAtTheIndicator) {
    AppContext ctx = hill_context();
    elevate_current(ctx, Dir::v);
    EXPECT_EQ(std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface.degree_v, 4);
    ctx.doc.indicator = {0.75, 0.4};
    ASSERT_TRUE(split_state(ctx, Dir::u).enabled);
    split_at_indicator(ctx, Dir::u);
    ASSERT_EQ(ctx.doc.objects.size(), 2u);
    // The indicator keeps its place over the shared domain: (0.75, 0.4) in both pieces' group.
    const doc::Object& left = ctx.doc.objects[0];
    EXPECT_EQ(indicator_params(ctx.doc, left), glm::dvec2(0.75, 0.4));
    // On the edge of the current patch a split is refused with a reason.
    ctx.doc.selection = {left.id, -1, -1};
    ctx.doc.indicator = {0.75, 0.4};
    const ActionState edge = split_state(ctx, Dir::u);
    EXPECT_FALSE(edge.enabled);
    EXPECT_FALSE(edge.why.empty());
    // Moving the indicator right of 0.75 makes the second piece current.
    ctx.doc.indicator = {0.9, 0.4};
    EXPECT_TRUE(doc::follow_indicator(ctx.doc, left.id));
    EXPECT_EQ(ctx.doc.selection.object, ctx.doc.objects[1].id);
    // Evaluation never leaves a patch's own domain, even for a frame in which the indicator
    // lies in another patch's part of the square.
    EXPECT_EQ(indicator_params(ctx.doc, ctx.doc.objects[0]), glm::dvec2(0.75, 0.4));
}

} // namespace
