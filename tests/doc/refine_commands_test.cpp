// Knot insertion, degree elevation and split as document commands: exact undo, unchanged
// shape, refusals that touch nothing, and the selection following its control point.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::Dir;
using geom::ErrorCode;

namespace {

void expect_same_shape(const geom::Surface& a, const geom::Surface& b, double u0, double u1,
                       double v0, double v1) {
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) {
            const double u = u0 + (u1 - u0) * i / 10, v = v0 + (v1 - v0) * j / 10;
            const auto pa = geom::surface_point(a, u, v), pb = geom::surface_point(b, u, v);
            ASSERT_EQ(pa.has_value(), pb.has_value());
            if (pa) {
                EXPECT_LT(glm::length(*pa - *pb), 1e-12) << u << " " << v;
            }
        }
}

void expect_same_curve_shape(const geom::Curve& a, const geom::Curve& b, double t0, double t1) {
    for (int k = 0; k <= 40; ++k) {
        const double t = t0 + (t1 - t0) * k / 40;
        const auto pa = geom::curve_point(a, t), pb = geom::curve_point(b, t);
        ASSERT_EQ(pa.has_value(), pb.has_value());
        if (pa) {
            EXPECT_LT(glm::length(*pa - *pb), 1e-12) << t;
        }
    }
}

TEST(InsertKnotCommand, UndoRedoExactAndShapeUnchanged) {
    Document doc = sample_document();
    const geom::Surface before = surface_of(doc, hill_id);
    const Document after = expect_undo_redo_exact(doc, insert_knot(hill_id, Dir::u, 0.75));
    const geom::Surface& s = surface_of(after, hill_id);
    EXPECT_EQ(s.n_u, 6);
    EXPECT_EQ(s.knots_u.size(), before.knots_u.size() + 1);
    EXPECT_EQ(s.knots_v, before.knots_v);
    expect_same_shape(before, s, 0, 1, 0, 1);
}

TEST(InsertKnotCommand, CurveAndMultipleTimes) {
    Document doc = sample_document();
    const geom::Curve before = curve_of(doc, curve_id);
    const Document after = expect_undo_redo_exact(doc, insert_knot(curve_id, Dir::u, 0.6, 2));
    EXPECT_EQ(curve_of(after, curve_id).count(), before.count() + 2);
    expect_same_curve_shape(before, curve_of(after, curve_id), 0, 1);
}

TEST(InsertKnotCommand, BezierBecomesBspline) {
    Document doc = sample_document();
    const Document after = expect_undo_redo_exact(doc, insert_knot(patch_id, Dir::v, 0.5));
    EXPECT_EQ(surface_of(after, patch_id).type, geom::SplineType::bspline);
    EXPECT_EQ(surface_of(doc, patch_id).type, geom::SplineType::bspline);
}

TEST(InsertKnotCommand, ARationalBezierBecomingNurbsSaysSo) {
    Document doc = sample_document();
    geom::Surface rational = surface_of(doc, patch_id);
    rational.type = geom::SplineType::rational_bezier;
    rational.weight(1, 1) = 3;
    History h;
    ASSERT_TRUE(h.execute(doc, edit_shape(patch_id, SurfaceObject{rational}, "Rational")).ok());
    auto cmd = insert_knot(patch_id, Dir::u, 0.5);
    const Command* insertion = cmd.get();
    EXPECT_EQ(refinement_type_change(*insertion), ""); // not applied yet
    ASSERT_TRUE(h.execute(doc, std::move(cmd)).ok());
    EXPECT_EQ(surface_of(doc, patch_id).type, geom::SplineType::nurbs);
    EXPECT_EQ(refinement_type_change(*insertion), "rational Bezier becomes NURBS");
    EXPECT_EQ(h.undo_label(), "Insert knot u = 0.5 (rational Bezier becomes NURBS)");
    // Already NURBS: nothing to say.
    ASSERT_TRUE(h.execute(doc, insert_knot(patch_id, Dir::u, 0.25)).ok());
    EXPECT_EQ(h.undo_label(), "Insert knot u = 0.25");
    // Elevation keeps a Bezier a Bezier; other commands have no type change.
    EXPECT_EQ(refinement_type_change(*split_object(patch_id, Dir::u, 0.5)), "");
}

TEST(InsertKnotCommand, Label) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.75)).ok());
    EXPECT_EQ(h.undo_label(), "Insert knot u = 0.75");
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::v, 0.25, 2)).ok());
    EXPECT_EQ(h.undo_label(), "Insert knot v = 0.25 (2 times)");
}

TEST(InsertKnotCommand, RefusalsPassGeometryPathsThrough) {
    Document doc = sample_document();
    expect_refused(doc, insert_knot(hill_id, Dir::u, 1.5), ErrorCode::domain, "/knot");
    expect_refused(doc, insert_knot(hill_id, Dir::u, -0.1), ErrorCode::domain, "/knot");
    expect_refused(doc, insert_knot(hill_id, Dir::u, std::nan("")), ErrorCode::domain, "/knot");
    expect_refused(doc, insert_knot(hill_id, Dir::u, 0.5, 3), ErrorCode::multiplicity, "/times");
    expect_refused(doc, insert_knot(hill_id, Dir::u, 0.0), ErrorCode::multiplicity, "/times");
    expect_refused(doc, insert_knot(hill_id, Dir::u, 0.3, 0), ErrorCode::schema, "/times");
    expect_refused(doc, insert_knot(curve_id, Dir::v, 0.3), ErrorCode::schema, "/direction");
    expect_refused(doc, insert_knot(ball_id, Dir::u, 0.3), ErrorCode::schema, "/id");
    expect_refused(doc, insert_knot(99, Dir::u, 0.3), ErrorCode::schema, "/id");
}

TEST(InsertKnotCommand, SelectionFollowsItsControlPoint) {
    // Default hill: p = 3, U = 0 0 0 0 0.5 1 1 1 1. Inserting 0.75 (span k = 4, s = 0) keeps
    // P0, P1, shifts P4 to P5 and replaces P2, P3.
    struct Case {
        int i, expected;
    };
    for (Case c : {Case{0, 0}, Case{1, 1}, Case{4, 5}, Case{2, 2}}) {
        Document doc = sample_document();
        doc.view.selection = Selection{hill_id, c.i, 3};
        const Document before = doc;
        History h;
        ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.75)).ok());
        EXPECT_EQ(doc.view.selection, (Selection{hill_id, c.expected, 3})) << "i = " << c.i;
        h.undo(doc);
        EXPECT_EQ(doc.view.selection, before.view.selection);
    }
    // Along v, only j moves; selection on another object is untouched.
    Document doc = sample_document();
    doc.view.selection = Selection{hill_id, 3, 4};
    History h;
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::v, 0.25)).ok());
    EXPECT_EQ(doc.view.selection, (Selection{hill_id, 3, 5}));
    doc.view.selection = Selection{grid_id, 1, 1};
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::v, 0.3)).ok());
    EXPECT_EQ(doc.view.selection, (Selection{grid_id, 1, 1}));
}

TEST(InsertKnotCommand, UndoMapsALaterSelectionBack) {
    Document doc = sample_document();
    doc.view.selection = Selection{hill_id, 1, 1};
    History h;
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.75)).ok());
    doc.view.selection = Selection{hill_id, 5, 2}; // the user picks the last row after inserting
    h.undo(doc);
    EXPECT_EQ(doc.view.selection, (Selection{hill_id, 4, 2}));
}

TEST(ElevateDegreeCommand, UndoRedoExactAndShapeUnchanged) {
    Document doc = sample_document();
    const geom::Surface before = surface_of(doc, hill_id);
    const Document after = expect_undo_redo_exact(doc, elevate_degree(hill_id, Dir::v));
    const geom::Surface& s = surface_of(after, hill_id);
    EXPECT_EQ(s.degree_v, 4);
    EXPECT_EQ(s.degree_u, 3);
    EXPECT_EQ(s.n_v, 7); // two spans: one new point per span
    expect_same_shape(before, s, 0, 1, 0, 1);
}

TEST(ElevateDegreeCommand, CurveTwiceAndBezierKeepsItsType) {
    Document doc = sample_document();
    const geom::Curve before = curve_of(doc, curve_id);
    const Document after = expect_undo_redo_exact(doc, elevate_degree(curve_id, Dir::u, 2));
    EXPECT_EQ(curve_of(after, curve_id).degree, 5);
    expect_same_curve_shape(before, curve_of(after, curve_id), 0, 1);

    const Document after2 = expect_undo_redo_exact(doc, elevate_degree(patch_id, Dir::u));
    EXPECT_EQ(surface_of(after2, patch_id).type, geom::SplineType::bezier);
    EXPECT_EQ(surface_of(after2, patch_id).n_u, 4);
}

TEST(ElevateDegreeCommand, Labels) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, elevate_degree(hill_id, Dir::v)).ok());
    EXPECT_EQ(h.undo_label(), "Elevate degree in v");
    ASSERT_TRUE(h.execute(doc, elevate_degree(hill_id, Dir::u, 2)).ok());
    EXPECT_EQ(h.undo_label(), "Elevate degree in u by 2");
    ASSERT_TRUE(h.execute(doc, elevate_degree(curve_id, Dir::u)).ok());
    EXPECT_EQ(h.undo_label(), "Elevate degree");
}

TEST(ElevateDegreeCommand, Refusals) {
    Document doc = sample_document();
    expect_refused(doc, elevate_degree(hill_id, Dir::u, 0), ErrorCode::schema, "/times");
    expect_refused(doc, elevate_degree(hill_id, Dir::u, -3), ErrorCode::schema, "/times");
    expect_refused(doc, elevate_degree(hill_id, Dir::u, 2000000000), ErrorCode::limit, "/times");
    expect_refused(doc, elevate_degree(curve_id, Dir::u, 5000), ErrorCode::limit, "/times");
    expect_refused(doc, elevate_degree(curve_id, Dir::v), ErrorCode::schema, "/direction");
    expect_refused(doc, elevate_degree(ball_id, Dir::u), ErrorCode::schema, "/id");
}

TEST(ElevateDegreeCommand, SelectionKeepsEndsAndNearestPoint) {
    for (int i : {0, 4}) {
        Document doc = sample_document();
        doc.view.selection = Selection{hill_id, i, 2};
        History h;
        ASSERT_TRUE(h.execute(doc, elevate_degree(hill_id, Dir::u)).ok());
        EXPECT_EQ(doc.view.selection, (Selection{hill_id, i == 0 ? 0 : 6, 2}));
        h.undo(doc);
        EXPECT_EQ(doc.view.selection, (Selection{hill_id, i, 2}));
    }
    // The middle point (Greville abscissa 0.5) goes to the new point at 0.5 (index 3 of 7).
    Document doc = sample_document();
    doc.view.selection = Selection{hill_id, 2, 2};
    History h;
    ASSERT_TRUE(h.execute(doc, elevate_degree(hill_id, Dir::u)).ok());
    EXPECT_EQ(doc.view.selection, (Selection{hill_id, 3, 2}));
}

TEST(SplitCommand, PiecesReplaceTheObjectInPlace) {
    Document doc = sample_document();
    const geom::Surface whole = surface_of(doc, hill_id);
    History h;
    auto cmd = split_object(hill_id, Dir::u, 0.75);
    const Command* raw = cmd.get();
    EXPECT_EQ(split_piece_ids(*raw), (std::pair<std::uint64_t, std::uint64_t>{0, 0}));
    ASSERT_TRUE(h.execute(doc, std::move(cmd)).ok());
    const auto ids = split_piece_ids(*raw);
    EXPECT_EQ(ids.first, 6u);
    EXPECT_EQ(ids.second, 7u);
    ASSERT_EQ(doc.objects.size(), 6u);
    EXPECT_EQ(doc.objects[0].id, ids.first);
    EXPECT_EQ(doc.objects[1].id, ids.second);
    EXPECT_EQ(doc.objects[0].name, "hill.1");
    EXPECT_EQ(doc.objects[1].name, "hill.2");
    EXPECT_EQ(doc.objects[2].id, curve_id);
    EXPECT_EQ(doc.find(hill_id), nullptr);
    EXPECT_EQ(h.undo_label(), "Split at u = 0.75");
    const auto& a = surface_of(doc, ids.first);
    const auto& b = surface_of(doc, ids.second);
    EXPECT_EQ(a.knots_u.front(), 0.0);
    EXPECT_EQ(a.knots_u.back(), 0.75);
    EXPECT_EQ(b.knots_u.front(), 0.75);
    EXPECT_EQ(b.knots_u.back(), 1.0);
    expect_same_shape(whole, a, 0, 0.75, 0, 1);
    expect_same_shape(whole, b, 0.75, 1, 0, 1);
    // Undo restores the whole object at its place; redo brings back the same ids.
    h.undo(doc);
    EXPECT_EQ(doc.objects[0].id, hill_id);
    h.redo(doc);
    EXPECT_EQ(split_piece_ids(*raw), ids);
    EXPECT_EQ(doc.objects[0].id, ids.first);
    EXPECT_EQ(doc.objects[1].id, ids.second);
}

TEST(SplitCommand, UndoRedoExactWithTheSameIds) {
    Document doc = sample_document();
    const Document after = expect_undo_redo_exact(doc, split_object(hill_id, Dir::v, 0.5));
    EXPECT_TRUE(same_document(doc, after));
    EXPECT_EQ(doc.next_id, 8u);
    // A piece splits again (the paper: u = 0.75, then the left part at v = 0.5).
    Document doc2 = sample_document();
    History h;
    auto first = split_object(hill_id, Dir::u, 0.75);
    const Command* raw = first.get();
    ASSERT_TRUE(h.execute(doc2, std::move(first)).ok());
    const Document mid = doc2;
    ASSERT_TRUE(h.execute(doc2, split_object(split_piece_ids(*raw).first, Dir::v, 0.5)).ok());
    EXPECT_EQ(doc2.objects[0].name, "hill.1.1");
    EXPECT_EQ(doc2.objects[1].name, "hill.1.2");
    EXPECT_EQ(doc2.objects[2].name, "hill.2");
    h.undo(doc2);
    EXPECT_TRUE(same_document(doc2, mid));
    h.undo(doc2);
    EXPECT_TRUE(same_document(doc2, sample_document()));
}

TEST(SplitCommand, CurveSplits) {
    Document doc = sample_document();
    const geom::Curve whole = curve_of(doc, curve_id);
    const Document after = expect_undo_redo_exact(doc, split_object(curve_id, Dir::u, 0.4));
    ASSERT_EQ(after.objects[1].name, "profile.1");
    ASSERT_EQ(after.objects[2].name, "profile.2");
    const auto& pa = std::get<CurveObject>(after.objects[1].shape);
    EXPECT_EQ(pa.plane, CurvePlane::xy);
    expect_same_curve_shape(whole, pa.curve, 0, 0.4);
    expect_same_curve_shape(whole, std::get<CurveObject>(after.objects[2].shape).curve, 0.4, 1);
}

TEST(SplitCommand, Refusals) {
    Document doc = sample_document();
    expect_refused(doc, split_object(hill_id, Dir::u, 0.0), ErrorCode::domain, "/param");
    expect_refused(doc, split_object(hill_id, Dir::u, 1.0), ErrorCode::domain, "/param");
    expect_refused(doc, split_object(hill_id, Dir::v, 2.0), ErrorCode::domain, "/param");
    expect_refused(doc, split_object(curve_id, Dir::v, 0.5), ErrorCode::schema, "/direction");
    expect_refused(doc, split_object(ball_id, Dir::u, 0.5), ErrorCode::schema, "/id");
}

TEST(SplitCommand, SelectionGoesToThePieceHoldingThePoint) {
    struct Case {
        int i;
        int piece; // 0 first, 1 second
        int expected;
    };
    // Hill u: Greville abscissae 0, 1/6, 1/2, 5/6, 1. Split at 0.75: P0, P1, P2 stay in the
    // first piece with their indices; P3 and P4 go to the second piece.
    for (Case c : {Case{0, 0, 0}, Case{1, 0, 1}, Case{2, 0, 2}, Case{4, 1, 3}}) {
        Document doc = sample_document();
        doc.view.selection = Selection{hill_id, c.i, 1};
        History h;
        auto cmd = split_object(hill_id, Dir::u, 0.75);
        const Command* raw = cmd.get();
        ASSERT_TRUE(h.execute(doc, std::move(cmd)).ok());
        const auto ids = split_piece_ids(*raw);
        EXPECT_EQ(doc.view.selection,
                  (Selection{c.piece == 0 ? ids.first : ids.second, c.expected, 1}))
            << "i = " << c.i;
        // The remapped point is the same point when the piece kept it.
        const geom::Surface& piece = surface_of(doc, doc.view.selection.object);
        if (c.i != 2) {
            EXPECT_EQ(piece.point(c.expected, 1),
                      surface_of(sample_document(), hill_id).point(c.i, 1));
        }
        h.undo(doc);
        EXPECT_EQ(doc.view.selection, (Selection{hill_id, c.i, 1}));
    }
    // Object selected without a point: the first piece.
    Document doc = sample_document();
    doc.view.selection = Selection{hill_id, -1, -1};
    History h;
    ASSERT_TRUE(h.execute(doc, split_object(hill_id, Dir::v, 0.5)).ok());
    EXPECT_EQ(doc.view.selection, (Selection{doc.objects[0].id, -1, -1}));
    // Selecting a point of the second piece, then undoing, selects it on the whole object.
    doc.view.selection = Selection{doc.objects[1].id, 2, 3}; // the last column of the second piece
    h.undo(doc);
    EXPECT_EQ(doc.view.selection.object, hill_id);
    EXPECT_EQ(doc.view.selection.i, 2);
    EXPECT_EQ(doc.view.selection.j, 4);
}

} // namespace
