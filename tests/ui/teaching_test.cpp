// Teaching in the workstation: de Boor's step control and overlay, the actions at the
// indicator (insert, elevate, split) and the indicator over a patch group's shared domain.
#include <gtest/gtest.h>

#include "core/doc/commands.hpp"
#include "core/doc/patches.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/knots.hpp"
#include "ui/app_context.hpp"
#include "ui/surface_actions.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/current_patch.hpp"
#include "ui/view/deboor_overlay.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/scene_builder.hpp"

using namespace isoparm;
using namespace isoparm::ui;
using geom::Dir;

namespace {

AppContext hill_context() {
    AppContext ctx;
    ctx.doc = doc::default_document(); // bicubic 5x5 NURBS
    ctx.doc.view.selection = {ctx.doc.objects[0].id, -1, -1};
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
    EXPECT_TRUE(ctx.doc.view.display.deboor);
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

const PointBatch* batch_of_size(const Overlay& o, float size_over_scale, float scale = 1) {
    for (const PointBatch& b : o.points)
        if (b.size_px == size_over_scale * scale) return &b;
    return nullptr;
}

geom::DeBoorSurfaceTrace hill_trace(double u, double v) {
    const doc::Document d = doc::default_document();
    const geom::Surface& s = std::get<doc::SurfaceObject>(d.objects[0].shape).surface;
    return geom::deboor_surface(s, u, v);
}

TEST(DeBoorOverlay, StepZeroRingsTheActivePointsAndTheEndShowsSuv) {
    const geom::DeBoorSurfaceTrace trace = hill_trace(0.3, 0.6);
    Overlay first;
    add_deboor_overlay(trace, 3, 3, 0, 1, first);
    EXPECT_EQ(count_points(first, DeBoorSizes::acting_point), 16u); // (p_u + 1) x (p_v + 1)
    EXPECT_TRUE(first.lines.empty());
    EXPECT_EQ(count_points(first, DeBoorSizes::result_point), 0u);

    Overlay all;
    add_deboor_overlay(trace, 3, 3, -1, 1, all);
    ASSERT_EQ(count_points(all, DeBoorSizes::result_point), 1u); // the red sphere S(u, v)
    const glm::vec3 p = all.points.back().points[0].position;
    const auto expected = trace.point();
    ASSERT_TRUE(expected);
    EXPECT_NEAR(p.x, expected->x, 1e-6);
    EXPECT_NEAR(p.z, expected->z, 1e-6);
    // Every level at once, none faint: every row's three u levels (3 + 2 + 1 points) and
    // the v-stage's, all at one medium size.
    const float medium = (DeBoorSizes::current_point + DeBoorSizes::past_point) / 2;
    EXPECT_GT(count_points(all, medium), 5u * 6);
    EXPECT_EQ(count_points(all, DeBoorSizes::past_point), 0u);
}

TEST(DeBoorOverlay, TheCurrentLevelStandsOutAndThePastOnesAreFaint) {
    const geom::DeBoorSurfaceTrace trace = hill_trace(0.3, 0.6);
    const float scale = 1.5f; // presentation mode
    Overlay o;
    add_deboor_overlay(trace, 3, 3, 2, scale, o); // u-stage, level 2
    // Level 2 of each of the 5 row curves: 2 points each, large.
    const PointBatch* current = batch_of_size(o, DeBoorSizes::current_point, scale);
    ASSERT_NE(current, nullptr);
    EXPECT_EQ(current->points.size(), 5u * 2);
    // The rows the v-stage uses in full colour, the other row fainter.
    int opaque = 0;
    for (const OverlayVertex& v : current->points) opaque += v.color.a == 1.f;
    EXPECT_EQ(opaque, 4 * 2);
    // Passed: the 16 acting control points and level 1 (5 rows x 3 points), small and faint.
    const PointBatch* past = batch_of_size(o, DeBoorSizes::past_point, scale);
    ASSERT_NE(past, nullptr);
    EXPECT_EQ(past->points.size(), 16u + 5 * 3);
    for (const OverlayVertex& v : past->points) EXPECT_LT(v.color.a, 0.7f);
    // The current level's polylines are the thick ones; no S(u, v) yet.
    ASSERT_EQ(o.lines.size(), 2u);
    EXPECT_EQ(o.lines.back().width_px, DeBoorSizes::current_line * scale);
    EXPECT_EQ(o.lines.back().vertices.size(), 5u * 2); // one segment per row
    EXPECT_EQ(o.lines.front().width_px, DeBoorSizes::past_line * scale);
    EXPECT_EQ(count_points(o, DeBoorSizes::result_point, scale), 0u);

    // The last step: S(u, v) itself, with the v-stage's last level in front.
    Overlay end;
    add_deboor_overlay(trace, 3, 3, 7, 1, end);
    EXPECT_EQ(count_points(end, DeBoorSizes::result_point), 1u);
    EXPECT_EQ(count_points(end, DeBoorSizes::current_point), 1u);
}

TEST(DeBoorOverlay, LabelsNameTheCurrentLevelAsTheTabDoes) {
    const geom::DeBoorSurfaceTrace trace = hill_trace(0.3, 0.6);
    EXPECT_TRUE(deboor_step_labels(trace, 3, 3, -1).empty()); // all levels: no labels

    const std::vector<DeBoorLabel> acting = deboor_step_labels(trace, 3, 3, 0);
    ASSERT_EQ(acting.size(), 16u);
    const int i0 = trace.u_stage[0].first_index, j0 = trace.v_stage.first_index;
    EXPECT_EQ(acting[0].text, "P" + std::to_string(i0) + "," + std::to_string(j0));

    // u-stage level 2: 2 points on each of the 4 rows the v-stage uses.
    const std::vector<DeBoorLabel> level2 = deboor_step_labels(trace, 3, 3, 2);
    ASSERT_EQ(level2.size(), 4u * 2);
    const geom::DeBoorTriangle& row = trace.u_stage[static_cast<std::size_t>(j0)];
    EXPECT_EQ(level2[0].text, deboor_point_name(true, 2, row.first_index + 2, j0));
    EXPECT_EQ(level2[0].text,
              "d^2_" + std::to_string(row.first_index + 2) + "," + std::to_string(j0));
    const auto p = geom::DeBoorTriangle::cartesian(row.levels[2][0]);
    ASSERT_TRUE(p);
    EXPECT_EQ(level2[0].position, glm::vec3(*p));

    // The column polygon: Q_j for the 4 rows used; then the v-stage's levels; then S(u, v).
    const std::vector<DeBoorLabel> column = deboor_step_labels(trace, 3, 3, 4);
    ASSERT_EQ(column.size(), 4u);
    EXPECT_EQ(column[0].text, "Q" + std::to_string(j0));
    EXPECT_EQ(deboor_step_labels(trace, 3, 3, 6).size(), 2u);
    EXPECT_EQ(deboor_step_labels(trace, 3, 3, 6)[0].text, "d^2_" + std::to_string(j0 + 2));
    const std::vector<DeBoorLabel> end = deboor_step_labels(trace, 3, 3, 7);
    ASSERT_EQ(end.size(), 1u);
    EXPECT_EQ(end[0].text, "S(u,v)");
}

TEST(DeBoorSteps, TheStepIsClampedWhenTheSurfaceChanges) {
    AppContext ctx = hill_context();
    deboor_step(ctx, +100); // to the end: step 7 of 7
    EXPECT_EQ(ctx.ui.deboor.step, 7);
    // The current surface becomes one of degree (2, 1): 2 + 1 + 1 = 4 steps.
    geom::Surface small;
    small.type = geom::SplineType::bspline;
    small.degree_u = 2;
    small.degree_v = 1;
    small.n_u = 3;
    small.n_v = 2;
    small.knots_u = geom::clamped_uniform_knots(3, 2);
    small.knots_v = geom::clamped_uniform_knots(2, 1);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j) small.points.push_back({i, j, 0});
    small.weights.assign(6, 1.0);
    ASSERT_TRUE(ctx.execute(
        doc::edit_shape(ctx.doc.objects[0].id, doc::SurfaceObject{small}, "Smaller")));
    EXPECT_EQ(deboor_step_count(ctx), 4);
    ctx.ui.deboor.playing = true;
    deboor_tick(ctx, 0.0); // every frame
    EXPECT_EQ(ctx.ui.deboor.step, 4);
    EXPECT_FALSE(ctx.ui.deboor.playing); // at the end: nothing left to play
    // Stepping back from there goes to the step before the last, not to 6.
    deboor_step(ctx, -1);
    EXPECT_EQ(ctx.ui.deboor.step, 3);
    // "All" stays "all".
    ctx.ui.deboor.step = -1;
    clamp_deboor_step(ctx);
    EXPECT_EQ(ctx.ui.deboor.step, -1);
}

TEST(DeBoorSteps, ZoomFramesTheActingPatch) {
    AppContext ctx = hill_context();
    ctx.ui.view_rect = {0, 0, 800, 500};
    const Viewport vp{0, 0, 800, 500};
    ctx.doc.view.indicator = {0.9, 0.9};
    fit_to_points(ctx.ui.camera, scene_points(ctx.doc), vp.aspect());
    const double whole = ctx.ui.camera.distance;
    zoom_to_acting_patch(ctx);
    EXPECT_TRUE(ctx.doc.view.display.deboor);
    EXPECT_LT(ctx.ui.camera.distance, whole);
    const doc::Object& o = ctx.doc.objects[0];
    const geom::Surface& s = std::get<doc::SurfaceObject>(o.shape).surface;
    const glm::dvec2 uv = indicator_params(ctx.doc, o);
    const std::vector<glm::dvec3> acting =
        deboor_acting_points(geom::deboor_surface(s, uv.x, uv.y), s.degree_v);
    ASSERT_EQ(acting.size(), 16u);
    const glm::dmat4 m = view_projection(ctx.ui.camera, vp.aspect());
    for (const glm::dvec3& p : acting) {
        const Projected q = project(m, vp, p);
        EXPECT_TRUE(q.visible);
        EXPECT_GE(q.pixel.x, 0);
        EXPECT_LE(q.pixel.x, vp.w);
        EXPECT_GE(q.pixel.y, 0);
        EXPECT_LE(q.pixel.y, vp.h);
    }
    // The corner P0,0 does not act at (0.9, 0.9): it is left out of the frame.
    const Projected corner = project(m, vp, s.point(0, 0));
    EXPECT_TRUE(corner.pixel.x < 0 || corner.pixel.x > vp.w || corner.pixel.y < 0 ||
                corner.pixel.y > vp.h);
}

TEST(DeBoorOverlay, SceneBuilderFollowsTheDisplayFlagAndTheStep) {
    doc::Document d = doc::default_document();
    d.view.selection = {d.objects[0].id, -1, -1};
    SceneStyle style;
    const std::size_t without = build_scene(d, style).overlay.points.size();
    d.view.display.deboor = true;
    style.deboor_step = 0;
    const BuiltScene some = build_scene(d, style);
    style.deboor_step = -1;
    const BuiltScene all = build_scene(d, style);
    EXPECT_GT(some.overlay.points.size(), without);
    EXPECT_GT(all.overlay.points.size(), some.overlay.points.size());
}

TEST(SurfaceActions, InsertUpToTheDegreeThenRefuseShapeUnchanged) {
    AppContext ctx = hill_context();
    ctx.doc.view.indicator = {0.25, 0.5};
    const geom::Surface before = std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface;
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(insert_knot_state(ctx, Dir::u).enabled) << k;
        insert_knot_at_indicator(ctx, Dir::u);
        if (k == 0) {
            const ActionNote* done = current_action_note(ctx);
            ASSERT_NE(done, nullptr);
            EXPECT_FALSE(done->refused);
            EXPECT_NE(done->text.find("grows from 5 x 5 to 6 x 5"), std::string::npos)
                << done->text;
        }
    }
    const geom::Surface& after = std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface;
    EXPECT_EQ(geom::multiplicity(after.knots_u, 0.25), 3);
    EXPECT_EQ(after.n_u, before.n_u + 3);
    const ActionState full = insert_knot_state(ctx, Dir::u);
    EXPECT_FALSE(full.enabled);
    EXPECT_NE(full.why.find("multiplicity 3"), std::string::npos) << full.why;
    // A fourth U is refused, and the tracing panel's note says why (not only the status bar).
    insert_knot_at_indicator(ctx, Dir::u);
    const ActionNote* note = current_action_note(ctx);
    ASSERT_NE(note, nullptr);
    EXPECT_TRUE(note->refused);
    EXPECT_NE(note->text.find("multiplicity 3"), std::string::npos) << note->text;
    EXPECT_EQ(ctx.ui.status, note->text);
    EXPECT_EQ(ctx.history.size(), 3u); // three undo steps, one per insertion
    ctx.history.undo(ctx.doc);
    EXPECT_EQ(current_action_note(ctx), nullptr); // the next edit (here undo) retires it
    ctx.history.undo(ctx.doc);
    ctx.history.undo(ctx.doc);
    EXPECT_EQ(std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface.points, before.points);
}

TEST(SurfaceActions, ARationalBezierBecomingNurbsIsSaid) {
    AppContext ctx = hill_context();
    geom::Surface s = std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface;
    s.type = geom::SplineType::rational_bezier;
    s.knots_u = {0, 0, 0, 0, 0, 1, 1, 1, 1, 1}; // degree 4 x 4 on the 5 x 5 net
    s.knots_v = s.knots_u;
    s.degree_u = s.degree_v = 4;
    ASSERT_TRUE(ctx.execute(
        doc::edit_shape(ctx.doc.objects[0].id, doc::SurfaceObject{s}, "Rational Bezier")));
    ctx.doc.view.indicator = {0.5, 0.5};
    insert_knot_at_indicator(ctx, Dir::v);
    EXPECT_EQ(std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface.type,
              geom::SplineType::nurbs);
    const ActionNote* note = current_action_note(ctx);
    ASSERT_NE(note, nullptr);
    EXPECT_FALSE(note->refused);
    EXPECT_NE(note->text.find("rational Bezier becomes NURBS"), std::string::npos) << note->text;
    EXPECT_NE(ctx.history.undo_label().find("becomes NURBS"), std::string::npos);
}

TEST(SurfaceActions, ElevateAndSplitAtTheIndicator) {
    AppContext ctx = hill_context();
    elevate_current(ctx, Dir::v);
    EXPECT_EQ(std::get<doc::SurfaceObject>(ctx.doc.objects[0].shape).surface.degree_v, 4);
    ctx.doc.view.indicator = {0.75, 0.4};
    ASSERT_TRUE(split_state(ctx, Dir::u).enabled);
    split_at_indicator(ctx, Dir::u);
    ASSERT_EQ(ctx.doc.objects.size(), 2u);
    // The indicator keeps its place over the shared domain: (0.75, 0.4) in both pieces' group.
    const doc::Object& left = ctx.doc.objects[0];
    EXPECT_EQ(indicator_params(ctx.doc, left), glm::dvec2(0.75, 0.4));
    // On the edge of the current patch a split is refused with a reason.
    ctx.doc.view.selection = {left.id, -1, -1};
    ctx.doc.view.indicator = {0.75, 0.4};
    const ActionState edge = split_state(ctx, Dir::u);
    EXPECT_FALSE(edge.enabled);
    EXPECT_FALSE(edge.why.empty());
    // Moving the indicator right of 0.75 makes the second piece current.
    ctx.doc.view.indicator = {0.9, 0.4};
    EXPECT_TRUE(ui::follow_indicator(ctx.doc, left.id));
    EXPECT_EQ(ctx.doc.view.selection.object, ctx.doc.objects[1].id);
    // Evaluation never leaves a patch's own domain, even for a frame in which the indicator
    // lies in another patch's part of the square.
    EXPECT_EQ(indicator_params(ctx.doc, ctx.doc.objects[0]), glm::dvec2(0.75, 0.4));
}

// The paper's Fig. 6 done live, as a lecture does it: C1 on, the indicator to u = 0.75 and
// S, the indicator into the left piece and Shift+S at v = 0.5. Every border then pairs up
// point for point, and one undo takes the second split back with the refinement it made.
TEST(SurfaceActions, Fig6SplitSequenceLiveKeepsEveryBorder) {
    AppContext ctx = hill_context();
    ctx.doc.continuity = doc::Continuity::c1;
    ctx.doc.view.indicator = {0.75, 0.5};
    split_at_indicator(ctx, Dir::u);
    ASSERT_EQ(ctx.doc.objects.size(), 2u);
    const std::uint64_t group = ctx.doc.objects[0].patch_group;
    ctx.doc.view.indicator = {0.3, 0.5};
    ui::sync_patch_and_indicator(ctx.doc, ctx.doc.view.selection.object, {0.75, 0.5},
                                 ctx.doc.view.selection.object);
    ASSERT_EQ(ctx.doc.view.selection.object, ctx.doc.objects[0].id); // the left piece
    const doc::Document after_first = ctx.doc;
    split_at_indicator(ctx, Dir::v);
    ASSERT_EQ(ctx.doc.objects.size(), 3u);
    const std::vector<doc::SharedBorder> borders = doc::shared_borders(ctx.doc, group);
    ASSERT_EQ(borders.size(), 3u);
    for (const doc::SharedBorder& b : borders) EXPECT_TRUE(b.conforming) << b.why_not;
    EXPECT_NE(ctx.ui.status.find("refined"), std::string::npos) << ctx.ui.status;
    EXPECT_NE(ctx.history.undo_label().find("1 neighbour refined"), std::string::npos)
        << ctx.history.undo_label();
    ctx.history.undo(ctx.doc);
    EXPECT_TRUE(doc::same_geometry(ctx.doc, after_first));
}

// The same sequence with continuity off, then C1 chosen afterwards (the tracing panel's
// "Keep across borders"): the borders are paired up then, in one undo step, and said so.
TEST(SurfaceActions, ContinuitySwitchedOnLaterPairsTheBordersUp) {
    AppContext ctx = hill_context();
    ctx.doc.view.indicator = {0.75, 0.5};
    split_at_indicator(ctx, Dir::u);
    const std::uint64_t group = ctx.doc.objects[0].patch_group;
    split_at_indicator(ctx, Dir::v); // the left piece is current after the first split
    ASSERT_EQ(ctx.doc.objects.size(), 3u);
    auto conforming = [&] {
        int n = 0;
        for (const doc::SharedBorder& b : doc::shared_borders(ctx.doc, group)) n += b.conforming;
        return n;
    };
    EXPECT_EQ(conforming(), 1);
    const std::size_t steps = ctx.history.size();
    set_continuity(ctx, doc::Continuity::c1);
    EXPECT_EQ(ctx.doc.continuity, doc::Continuity::c1);
    EXPECT_EQ(conforming(), 3);
    EXPECT_EQ(ctx.history.size(), steps + 1);
    const ActionNote* note = current_action_note(ctx);
    ASSERT_NE(note, nullptr);
    EXPECT_NE(note->text.find("v = 0.5 x2"), std::string::npos) << note->text;
    // Choosing C1 again has nothing left to do.
    set_continuity(ctx, doc::Continuity::c0);
    set_continuity(ctx, doc::Continuity::c1);
    EXPECT_EQ(ctx.history.size(), steps + 1);
    ctx.history.undo(ctx.doc);
    EXPECT_EQ(conforming(), 1);
}

} // namespace
