// The toolbox as document commands: knot removal, degree reduction, knot splitting, closing and
// type conversion undo exactly, replay from JSON, give the original back where they invert a
// refinement, and refuse (touching nothing) with the value at fault.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/doc/commands_curve.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/reshape.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::Dir;
using geom::ErrorCode;

namespace {

double max_point_distance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    EXPECT_EQ(a.size(), b.size());
    double d = 0;
    for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
        d = std::max(d, glm::length(a[k] - b[k]));
    return d;
}

// Applies cmd through a history and returns its label (the command must apply).
std::string run(Document& doc, History& h, std::unique_ptr<Command> cmd) {
    const auto st = h.execute(doc, std::move(cmd));
    EXPECT_TRUE(st.ok()) << (st.ok() ? "" : st.error().message);
    return h.undo_label();
}

TEST(RemoveKnotCommand, InsertThenRemoveGivesTheSurfaceBack) {
    Document doc = sample_document();
    const geom::Surface original = surface_of(doc, hill_id);
    History h;
    run(doc, h, insert_knot(hill_id, Dir::u, 0.3));
    ASSERT_EQ(surface_of(doc, hill_id).n_u, original.n_u + 1);
    const Document after = expect_undo_redo_exact(doc, remove_knot(hill_id, Dir::u, 0.3, 1, 1e-9));
    const geom::Surface& s = surface_of(after, hill_id);
    EXPECT_EQ(s.knots_u, original.knots_u);
    EXPECT_LT(max_point_distance(s.points, original.points), 1e-12);
}

TEST(RemoveKnotCommand, CurveRemovesFewerTimesThanAskedAndSaysSo) {
    Document doc = sample_document();
    const geom::Curve original = curve_of(doc, curve_id);
    History h;
    run(doc, h, insert_knot(curve_id, Dir::u, 0.75));
    const std::string label = run(doc, h, remove_knot(curve_id, Dir::u, 0.75, 2, 1e-9));
    EXPECT_NE(label.find("1 of 2 times"), std::string::npos) << label;
    EXPECT_EQ(curve_of(doc, curve_id).knots, original.knots);
    EXPECT_LT(max_point_distance(curve_of(doc, curve_id).points, original.points), 1e-12);
}

TEST(RemoveKnotCommand, AnEssentialKnotIsRefusedWithHowFarItWouldMove) {
    Document doc = sample_document();
    auto cmd = remove_knot(grid_id, Dir::u, 0.5, 1, 1e-9);
    const auto st = cmd->check(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("would move the surface by"), std::string::npos)
        << st.error().message;
    expect_refused(doc, std::move(cmd), ErrorCode::geometry, "/knot");
    // The sample curve has a negative weight: no bound is known, and the message says so.
    auto negative = remove_knot(curve_id, Dir::u, 0.25, 1, 1e-9);
    const auto why = negative->check(doc);
    ASSERT_FALSE(why.ok());
    EXPECT_NE(why.error().message.find("weight <= 0"), std::string::npos) << why.error().message;
    expect_refused(doc, remove_knot(hill_id, Dir::u, 0.4, 1, 1e-9), ErrorCode::schema, "/knot");
    expect_refused(doc, remove_knot(hill_id, Dir::u, 0.5, 1, -1), ErrorCode::schema, "/tolerance");
    expect_refused(doc, remove_knot(ball_id, Dir::u, 0.5, 1, 1), ErrorCode::schema, "/id");
}

TEST(ReduceDegreeCommand, ElevateThenReduceGivesTheSurfaceBack) {
    Document doc = sample_document();
    const geom::Surface original = surface_of(doc, grid_id);
    History h;
    run(doc, h, elevate_degree(grid_id, Dir::v));
    const Document after = expect_undo_redo_exact(doc, reduce_degree(grid_id, Dir::v, 1e-9));
    const geom::Surface& s = surface_of(after, grid_id);
    EXPECT_EQ(s.degree_v, original.degree_v);
    EXPECT_EQ(s.knots_v, original.knots_v);
    EXPECT_LT(max_point_distance(s.points, original.points), 1e-12);
}

TEST(ReduceDegreeCommand, OverTheToleranceIsRefusedWithTheBound) {
    Document doc = sample_document();
    auto cmd = reduce_degree(curve_id, Dir::u, 1e-9);
    const auto st = cmd->check(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::geometry);
    expect_refused(doc, std::move(cmd), ErrorCode::geometry, "/curve");
}

TEST(SplitKnotCommand, ADoubleKnotBecomesTwoAndTheShapeMovesALittle) {
    Document doc = sample_document();
    const geom::Curve original = curve_of(doc, curve_id);
    const Document after = expect_undo_redo_exact(doc, split_knot(curve_id, Dir::u, 0.5, 0.01));
    const geom::Curve& c = curve_of(after, curve_id);
    EXPECT_EQ(c.points, original.points);
    EXPECT_EQ(geom::multiplicity(c.knots, 0.5), 1);
    EXPECT_EQ(geom::multiplicity(c.knots, 0.49), 1);
    History h;
    Document d = sample_document();
    const std::string label = run(d, h, split_knot(curve_id, Dir::u, 0.5, std::nullopt));
    EXPECT_NE(label.find("x2 becomes x1"), std::string::npos) << label;
    EXPECT_NE(label.find("moves at most"), std::string::npos) << label;
    expect_refused(doc, split_knot(curve_id, Dir::u, 0.25, std::nullopt), ErrorCode::schema,
                   "/knot");
}

TEST(CloseCommand, TheCurveMeetsItselfSmoothlyAndClosesOnce) {
    Document doc = sample_document();
    const geom::Curve original = curve_of(doc, curve_id);
    const Document after = expect_undo_redo_exact(doc, close_object(curve_id, Dir::u));
    const geom::Curve& c = curve_of(after, curve_id);
    ASSERT_EQ(c.count(), original.count() + c.degree);
    const double a = c.knots[c.degree], b = c.knots[c.count()];
    // C^(p-1) at the seam: position and the first p - 1 derivatives agree at both ends.
    const auto da = geom::curve_derivatives(c, a, c.degree - 1);
    const auto db = geom::curve_derivatives(c, b, c.degree - 1);
    ASSERT_TRUE(da && db);
    for (int k = 0; k < c.degree; ++k)
        EXPECT_LT(glm::length((*da)[k] - (*db)[k]), 1e-9 * (1 + glm::length((*da)[k]))) << k;
    expect_refused(doc, close_object(curve_id, Dir::u), ErrorCode::schema, "/direction");
}

TEST(CloseCommand, ASurfaceClosesInOneDirection) {
    Document doc = sample_document();
    const geom::Surface original = surface_of(doc, grid_id);
    const Document after = expect_undo_redo_exact(doc, close_object(grid_id, Dir::v));
    const geom::Surface& s = surface_of(after, grid_id);
    EXPECT_EQ(s.n_v, original.n_v + original.degree_v);
    EXPECT_EQ(s.n_u, original.n_u);
    expect_refused(doc, close_object(grid_id, Dir::v), ErrorCode::schema, "/direction");
}

TEST(ConvertCommand, AMultiSpanSurfaceBecomesItsBezierPiecesInItsPlace) {
    Document doc = sample_document();
    const geom::Surface original = surface_of(doc, grid_id);
    const int index = doc.index_of(grid_id);
    const std::size_t count = doc.objects.size();
    doc.view.selection = {grid_id, 1, 1};
    const Document after =
        expect_undo_redo_exact(doc, convert_object(grid_id, geom::SplineType::bezier));
    // 4 - 2 spans in u, 5 - 3 in v.
    ASSERT_EQ(after.objects.size(), count + 3);
    for (int k = 0; k < 4; ++k) {
        const Object& piece = after.objects[index + k];
        EXPECT_EQ(piece.name, "grid." + std::to_string(k + 1));
        EXPECT_EQ(piece.patch_group, grid_id);
        EXPECT_EQ(piece.surface()->type, geom::SplineType::bezier);
        // Each piece is the original on its part of the domain.
        const geom::Surface& p = *piece.surface();
        const double u = 0.5 * (p.knots_u.front() + p.knots_u.back());
        const double v = 0.5 * (p.knots_v.front() + p.knots_v.back());
        EXPECT_LT(glm::length(*geom::surface_point(p, u, v) - *geom::surface_point(original, u, v)),
                  1e-12);
    }
    EXPECT_EQ(after.view.selection.object, after.objects[index].id);
    EXPECT_FALSE(after.view.selection.has_point());
}

TEST(ConvertCommand, UnequalWeightsAreResetOnlyWhenAsked) {
    Document doc = sample_document();
    expect_refused(doc, convert_object(curve_id, geom::SplineType::bspline), ErrorCode::weights,
                   "/to");
    auto losses = conversion_losses(*doc.find(curve_id), geom::SplineType::bspline);
    ASSERT_TRUE(losses.ok());
    EXPECT_TRUE(losses->weights_differ);
    EXPECT_EQ(losses->pieces, 1);
    EXPECT_NE(losses->text.find("every weight becomes 1"), std::string::npos) << losses->text;
    const Document after =
        expect_undo_redo_exact(doc, convert_object(curve_id, geom::SplineType::bspline, true));
    const geom::Curve& c = curve_of(after, curve_id);
    EXPECT_EQ(c.type, geom::SplineType::bspline);
    EXPECT_EQ(c.weights, std::vector<double>(c.points.size(), 1.0));
    expect_refused(doc, convert_object(hill_id, surface_of(doc, hill_id).type), ErrorCode::schema,
                   "/to");
}

TEST(ConvertCommand, WhatIsLostIsSaidBeforehand) {
    Document doc = sample_document();
    auto none = conversion_losses(*doc.find(grid_id), geom::SplineType::nurbs);
    ASSERT_TRUE(none.ok());
    EXPECT_TRUE(none->text.empty()) << none->text;
    auto pieces = conversion_losses(*doc.find(grid_id), geom::SplineType::bezier);
    ASSERT_TRUE(pieces.ok());
    EXPECT_EQ(pieces->pieces, 4);
    EXPECT_NE(pieces->text.find("4 Bezier pieces"), std::string::npos) << pieces->text;
    EXPECT_FALSE(conversion_losses(*doc.find(ball_id), geom::SplineType::nurbs).ok());
    expect_undo_redo_exact(doc, convert_object(grid_id, geom::SplineType::nurbs));
}

} // namespace

namespace {

// The curve designer's closed knot mode: the polygon is edited, the curve stays closed.
const CurveObject& curve_object_of_id(const Document& doc, std::uint64_t id) {
    return *doc.find(id)->curve_object();
}

TEST(ClosedKnotMode, EditsKeepTheCurveClosed) {
    Document doc = sample_document();
    const int n = curve_of(doc, curve_id).count();
    Document closed =
        expect_undo_redo_exact(doc, set_curve_knot_mode(curve_id, CurveKnotMode::closed));
    const geom::Curve& c = curve_of(closed, curve_id);
    const int p = c.degree;
    ASSERT_EQ(c.count(), n + p);
    EXPECT_TRUE(geom::is_closed_periodic(c));
    // Moving a repeated point moves its twin, whichever of the two is dragged.
    Document moved = expect_undo_redo_exact(doc, move_curve_point(curve_id, n + 1, {9, 9, 0}));
    EXPECT_EQ(curve_of(moved, curve_id).points[1], glm::dvec3(9, 9, 0));
    EXPECT_TRUE(geom::is_closed_periodic(curve_of(moved, curve_id)));
    Document weighted = expect_undo_redo_exact(doc, set_weight(curve_id, 0, -1, 3.0));
    EXPECT_EQ(curve_of(weighted, curve_id).weights[static_cast<std::size_t>(n)], 3.0);
    EXPECT_TRUE(geom::is_closed_periodic(curve_of(weighted, curve_id)));
    Document inserted = expect_undo_redo_exact(doc, insert_curve_point(curve_id, 2, {1.5, 3, 0}));
    EXPECT_EQ(curve_of(inserted, curve_id).count(), n + 1 + p);
    EXPECT_TRUE(geom::is_closed_periodic(curve_of(inserted, curve_id)));
    Document deleted = expect_undo_redo_exact(doc, delete_curve_point(curve_id, 1));
    EXPECT_EQ(curve_of(deleted, curve_id).count(), n + 1 - 1 + p);
    EXPECT_TRUE(geom::is_closed_periodic(curve_of(deleted, curve_id)));
    Document lower = expect_undo_redo_exact(doc, set_curve_degree(curve_id, 2));
    EXPECT_EQ(curve_of(lower, curve_id).count(), n + 2);
    EXPECT_TRUE(geom::is_closed_periodic(curve_of(lower, curve_id)));
    // Back to an open mode: the polygon alone, clamped.
    Document open =
        expect_undo_redo_exact(doc, set_curve_knot_mode(curve_id, CurveKnotMode::clamped_uniform));
    EXPECT_EQ(curve_of(open, curve_id).count(), n);
    EXPECT_EQ(curve_object_of_id(open, curve_id).knot_mode, CurveKnotMode::clamped_uniform);
}

TEST(ClosedKnotMode, CloseLeavesTheCurveClosedForTheDesigner) {
    Document doc = sample_document();
    const Document after = expect_undo_redo_exact(doc, close_object(curve_id, Dir::u));
    EXPECT_EQ(curve_object_of_id(after, curve_id).knot_mode, CurveKnotMode::closed);
    auto made =
        new_curve_object("loop", CurvePlane::xy, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, 3,
                         CurveKnotMode::closed);
    ASSERT_TRUE(made.ok()) << made.error().message;
    EXPECT_TRUE(geom::is_closed_periodic(made->curve_object()->curve));
    auto short_loop = new_curve_object("loop", CurvePlane::xy, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, 3,
                                       CurveKnotMode::closed);
    ASSERT_FALSE(short_loop.ok());
}

} // namespace
