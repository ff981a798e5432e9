// A selected triangular patch in the teaching panels' actions: de Casteljau's steps through
// de Boor's step control (0 the control points .. n the point), and the panels' switch to the
// triangle only when the triangle is what is selected.
#include <gtest/gtest.h>

#include "core/doc/commands.hpp"
#include "core/doc/commands_triangle.hpp"
#include "ui/app_context.hpp"
#include "ui/surface_actions.hpp"
#include "ui/view/triangle_domain.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

// The default scene (a bicubic surface, id 1) plus a cubic triangle, selected.
AppContext triangle_context(int degree = 3) {
    AppContext ctx;
    ctx.doc = doc::default_document();
    doc::Object tri;
    tri.id = ctx.doc.allocate_id();
    tri.name = "tri";
    tri.shape = doc::TriangleObject{doc::make_flat_triangle(degree, true).value()};
    ctx.doc.objects.push_back(tri);
    ctx.doc.view.selection = {tri.id, 1, 1};
    return ctx;
}

TEST(TriangleSteps, TheSelectedTriangleHasNPlusOneSteps) {
    AppContext ctx = triangle_context();
    EXPECT_NE(selected_triangle(ctx.doc), nullptr);
    EXPECT_EQ(deboor_step_count(ctx), 3); // steps 0, 1, 2, 3: level 3 is the point
    deboor_step(ctx, +1);                 // from "all": the control points
    EXPECT_EQ(ctx.ui.deboor.step, 0);
    EXPECT_TRUE(ctx.doc.view.display.deboor);
    deboor_step(ctx, +10);
    EXPECT_EQ(ctx.ui.deboor.step, 3);
    deboor_step(ctx, -1);
    EXPECT_EQ(ctx.ui.deboor.step, 2);
    deboor_step(ctx, -10);
    EXPECT_EQ(ctx.ui.deboor.step, 0);
    // Playing ends on the point, after three steps.
    deboor_toggle_play(ctx, 10.0);
    double t = 10.0;
    int ticks = 0;
    while (deboor_tick(ctx, t += 1.0)) ++ticks;
    EXPECT_EQ(ctx.ui.deboor.step, 3);
    EXPECT_EQ(ticks, 2);
}

TEST(TriangleSteps, SelectingTheSurfaceAgainGivesDeBoorsSteps) {
    AppContext ctx = triangle_context();
    ctx.doc.view.selection = {1, -1, -1}; // the bicubic surface
    EXPECT_EQ(selected_triangle(ctx.doc), nullptr);
    EXPECT_EQ(deboor_step_count(ctx), 7); // 3 + 3 + 1
    // Nothing selected: the panels show the first surface, not the triangle.
    ctx.doc.view.selection = {};
    EXPECT_EQ(selected_triangle(ctx.doc), nullptr);
    EXPECT_EQ(deboor_step_count(ctx), 7);
}

TEST(TriangleSteps, ALowerDegreePullsTheStepBackToThePoint) {
    AppContext ctx = triangle_context(4);
    deboor_step(ctx, +1);
    deboor_step(ctx, +10);
    EXPECT_EQ(ctx.ui.deboor.step, 4);
    // The triangle replaced by a cubic one (as an undo of an elevation would): the counter
    // must not read "step 4 of 3".
    doc::Object& tri = ctx.doc.objects.back();
    std::get<doc::TriangleObject>(tri.shape).patch = doc::make_flat_triangle(3, true).value();
    clamp_deboor_step(ctx);
    EXPECT_EQ(ctx.ui.deboor.step, 3);
}

TEST(TriangleSteps, ElevatingTheTriangleAddsAStep) {
    AppContext ctx = triangle_context();
    const std::uint64_t id = ctx.doc.view.selection.object;
    ASSERT_TRUE(ctx.execute(doc::elevate_degree(id, geom::Dir::u, 1)));
    EXPECT_EQ(deboor_step_count(ctx), 4);
}

} // namespace
