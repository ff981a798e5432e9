// Editing commands: exact undo/redo, merging, labels and refusals that touch nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>

#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::Dir;
using geom::ErrorCode;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

TEST(MoveControlPoint, UndoRedoExact) {
    Document doc = sample_document();
    const Document after =
        expect_undo_redo_exact(doc, move_control_point(hill_id, 2, 3, {0.1, -0.2, 7}));
    EXPECT_EQ(surface_of(after, hill_id).point(2, 3), glm::dvec3(0.1, -0.2, 7));
    expect_undo_redo_exact(doc, move_control_point(curve_id, 4, -1, {1, 1, 1}));
    expect_undo_redo_exact(doc, move_control_point(patch_id, 2, 3, {1, 1, -0.0}));
}

TEST(MoveControlPoint, RestoresNegativeZeroExactly) {
    Document doc = sample_document();
    std::get<SurfaceObject>(doc.find(grid_id)->shape).surface.point(0, 0).z = -0.0;
    expect_undo_redo_exact(doc, move_control_point(grid_id, 0, 0, {0, 0, 0}));
    EXPECT_TRUE(std::signbit(surface_of(doc, grid_id).point(0, 0).z) == false);
}

TEST(MoveControlPoint, LabelsAndMerge) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 2, 3, {0, 0, 1})).ok());
    EXPECT_EQ(h.undo_label(), "Move P23");
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 2, 3, {0, 0, 2})).ok());
    EXPECT_EQ(h.size(), 1u);
    h.seal();
    ASSERT_TRUE(h.execute(doc, move_control_point(curve_id, 4, -1, {0, 0, 2})).ok());
    EXPECT_EQ(h.undo_label(), "Move P4");
    h.seal();
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.1)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.2)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.3)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.4)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.45)).ok());
    ASSERT_TRUE(h.execute(doc, insert_knot(hill_id, Dir::u, 0.46)).ok());
    h.seal();
    ASSERT_TRUE(h.execute(doc, move_control_point(hill_id, 10, 3, {0, 0, 1})).ok());
    EXPECT_EQ(h.undo_label(), "Move P10,3");
}

TEST(MoveControlPoint, Refusals) {
    Document doc = sample_document();
    expect_refused(doc, move_control_point(99, 0, 0, {0, 0, 0}), ErrorCode::schema, "/id");
    expect_refused(doc, move_control_point(hill_id, 5, 0, {0, 0, 0}), ErrorCode::schema, "/i");
    expect_refused(doc, move_control_point(hill_id, -1, 0, {0, 0, 0}), ErrorCode::schema, "/i");
    expect_refused(doc, move_control_point(hill_id, 0, 5, {0, 0, 0}), ErrorCode::schema, "/j");
    expect_refused(doc, move_control_point(curve_id, 1, 1, {0, 0, 0}), ErrorCode::schema, "/j");
    expect_refused(doc, move_control_point(ball_id, 0, 0, {0, 0, 0}), ErrorCode::schema, "/id");
    expect_refused(doc, move_control_point(hill_id, 0, 0, {0, inf, 0}), ErrorCode::schema,
                   "/position/1");
    expect_refused(doc, move_control_point(hill_id, 0, 0, {std::nan(""), 0, 0}), ErrorCode::schema,
                   "/position/0");
}

TEST(SetWeight, AnyFiniteWeightIncludingZeroAndNegative) {
    Document doc = sample_document();
    for (double w : {0.0, -2.5, 1e-300, 1e300, -0.0}) {
        const Document after = expect_undo_redo_exact(doc, set_weight(hill_id, 1, 1, w));
        EXPECT_EQ(surface_of(after, hill_id).weight(1, 1), w);
    }
    expect_undo_redo_exact(doc, set_weight(curve_id, 3, -1, 0.0));
}

TEST(SetWeight, LabelAndMerge) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 2, 2, 3)).ok());
    ASSERT_TRUE(h.execute(doc, set_weight(hill_id, 2, 2, 5)).ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Set weight w22 = 5");
    h.undo(doc);
    EXPECT_EQ(surface_of(doc, hill_id).weight(2, 2), 2.0);
}

TEST(SetWeight, Refusals) {
    Document doc = sample_document();
    expect_refused(doc, set_weight(hill_id, 0, 0, inf), ErrorCode::weights, "/weight");
    expect_refused(doc, set_weight(hill_id, 0, 0, -inf), ErrorCode::weights, "/weight");
    expect_refused(doc, set_weight(hill_id, 0, 0, std::nan("")), ErrorCode::weights, "/weight");
    // Non-rational types keep unit weights.
    expect_refused(doc, set_weight(grid_id, 0, 0, 2), ErrorCode::weights, "/weight");
    expect_refused(doc, set_weight(patch_id, 0, 0, 0), ErrorCode::weights, "/weight");
    expect_refused(doc, set_weight(grid_id, 9, 0, 1), ErrorCode::schema, "/i");
    // ...but setting a unit weight on them is a valid (if idle) edit.
    History h;
    EXPECT_TRUE(h.execute(doc, set_weight(grid_id, 0, 0, 1)).ok());
}

TEST(SetWeight, MessageNamesTheValue) {
    Document doc = sample_document();
    History h;
    auto st = h.execute(doc, set_weight(grid_id, 1, 2, 5));
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("w12 = 5"), std::string::npos) << st.error().message;
    EXPECT_NE(st.error().message.find("bspline"), std::string::npos) << st.error().message;
    st = h.execute(doc, set_weight(hill_id, 1, 2, inf));
    ASSERT_FALSE(st.ok());
    EXPECT_NE(st.error().message.find("inf"), std::string::npos) << st.error().message;
}

TEST(SetKnot, MovesWithinItsNeighbours) {
    Document doc = sample_document();
    // Hill u: 0 0 0 0 0.5 1 1 1 1; knot 4 is the only interior knot.
    Document after = expect_undo_redo_exact(doc, set_knot(hill_id, Dir::u, 4, 0.3));
    EXPECT_EQ(surface_of(after, hill_id).knots_u[4], 0.3);
    // Curve: 0 0 0 0 0.25 0.5 0.5 1 1 1 1; knot 5 may reach 0.25 (it then has multiplicity 2).
    after = expect_undo_redo_exact(doc, set_knot(curve_id, Dir::u, 5, 0.25));
    EXPECT_EQ(curve_of(after, curve_id).knots[5], 0.25);
    EXPECT_EQ(curve_of(after, curve_id).knots[6], 0.5);
}

TEST(SetKnot, LabelAndMerge) {
    Document doc = sample_document();
    History h;
    ASSERT_TRUE(h.execute(doc, set_knot(hill_id, Dir::v, 4, 0.4)).ok());
    ASSERT_TRUE(h.execute(doc, set_knot(hill_id, Dir::v, 4, 0.45)).ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Set knot v4 = 0.45");
    ASSERT_TRUE(h.execute(doc, set_knot(hill_id, Dir::u, 4, 0.45)).ok());
    EXPECT_EQ(h.size(), 2u);
    h.undo(doc);
    h.undo(doc);
    EXPECT_TRUE(same_document(doc, sample_document()));
}

TEST(SetKnot, Refusals) {
    Document doc = sample_document();
    expect_refused(doc, set_knot(hill_id, Dir::u, 0, -0.5), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(hill_id, Dir::u, 3, 0.0), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(hill_id, Dir::u, 5, 1.0), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(hill_id, Dir::u, 4, 1.2), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(hill_id, Dir::u, 4, -0.2), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(hill_id, Dir::u, 4, inf), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(hill_id, Dir::u, 9, 0.5), ErrorCode::schema, "/k");
    expect_refused(doc, set_knot(hill_id, Dir::u, -1, 0.5), ErrorCode::schema, "/k");
    // Moving onto the end knots would give multiplicity p + 2.
    expect_refused(doc, set_knot(hill_id, Dir::u, 4, 0.0), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(hill_id, Dir::u, 4, 1.0), ErrorCode::knots, "/value");
    // Bezier patches have no movable knot.
    expect_refused(doc, set_knot(patch_id, Dir::u, 2, 0.5), ErrorCode::knots, "/value");
    expect_refused(doc, set_knot(curve_id, Dir::v, 4, 0.3), ErrorCode::schema, "/direction");
    expect_refused(doc, set_knot(ball_id, Dir::u, 0, 0.3), ErrorCode::schema, "/id");
}

TEST(SetKnot, UnclampedEndKnotsMove) {
    Document doc;
    Object o;
    o.name = "open";
    geom::Curve c;
    c.type = geom::SplineType::bspline;
    c.degree = 2;
    c.knots = {0, 1, 2, 3, 4, 5, 6};
    c.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}, {3, 1, 0}};
    c.weights = {1, 1, 1, 1};
    o.shape = CurveObject{c, CurvePlane::xy};
    History h;
    ASSERT_TRUE(h.execute(doc, add_object(o)).ok());
    const auto id = doc.objects[0].id;
    expect_undo_redo_exact(doc, set_knot(id, Dir::u, 0, -1));
    expect_undo_redo_exact(doc, set_knot(id, Dir::u, 2, 1.5));
}

TEST(TransformObject, UndoRedoExactAndMerge) {
    Document doc = sample_document();
    const glm::dmat4 m = glm::translate(glm::dmat4(1), glm::dvec3(1, 2, 3));
    Document after = expect_undo_redo_exact(doc, transform_object(hill_id, m));
    EXPECT_EQ(surface_of(after, hill_id).point(0, 0), glm::dvec3(-1, 0, 3));

    const Document start = doc;
    History h;
    // A rotation drag: redo must give exactly the points the drag produced, not a recomputed
    // product of the matrices.
    for (int k = 1; k <= 5; ++k)
        ASSERT_TRUE(
            h.execute(doc, transform_object(hill_id,
                                            glm::rotate(glm::dmat4(1), 0.1, glm::dvec3(0, 0, 1)),
                                            "Rotate hill"))
                .ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Rotate hill");
    const Document dragged = doc;
    h.undo(doc);
    EXPECT_TRUE(same_document(doc, start));
    h.redo(doc);
    EXPECT_TRUE(same_document(doc, dragged));
    expect_undo_redo_exact(doc, transform_object(curve_id, m));
}

TEST(TransformObject, Refusals) {
    Document doc = sample_document();
    glm::dmat4 projective(1);
    projective[0][3] = 0.5;
    expect_refused(doc, transform_object(hill_id, projective), ErrorCode::schema, "/matrix");
    glm::dmat4 bad(1);
    bad[3][0] = inf;
    expect_refused(doc, transform_object(hill_id, bad), ErrorCode::schema, "/matrix");
    expect_refused(doc, transform_object(hill_id, glm::scale(glm::dmat4(1), glm::dvec3(1e308))),
                   ErrorCode::schema, "/matrix");
    expect_refused(doc, transform_object(ball_id, glm::dmat4(1)), ErrorCode::schema, "/id");
}

TEST(ObjectCommands, AddGivesAStableId) {
    Document doc = sample_document();
    Object o;
    o.name = "flat";
    o.shape = SurfaceObject{make_planar_grid(3, 3, 2, 2, geom::SplineType::nurbs)};
    const Document after = expect_undo_redo_exact(doc, add_object(o));
    EXPECT_EQ(after.objects.back().id, 6u);
    EXPECT_EQ(after.next_id, 7u);
    History h;
    ASSERT_TRUE(h.execute(doc, add_object(o)).ok());
    EXPECT_EQ(h.undo_label(), "Add flat");
}

TEST(ObjectCommands, AddRefusals) {
    Document doc = sample_document();
    Object o;
    o.name = "dup";
    o.id = hill_id;
    o.shape = SurfaceObject{make_planar_grid(3, 3, 2, 2, geom::SplineType::nurbs)};
    expect_refused(doc, add_object(o), ErrorCode::schema, "/id");
    o.id = 0;
    o.name = "";
    expect_refused(doc, add_object(o), ErrorCode::schema, "/name");
    o.name = "tab\there";
    expect_refused(doc, add_object(o), ErrorCode::schema, "/name");
    o.name = "bad";
    geom::Surface s = make_planar_grid(3, 3, 2, 2, geom::SplineType::bspline);
    s.weights[4] = 2; // a non-rational type keeps unit weights
    o.shape = SurfaceObject{s};
    expect_refused(doc, add_object(o), ErrorCode::weights, "/shape/weights/1/1");
    s = make_planar_grid(3, 3, 2, 2, geom::SplineType::nurbs);
    s.knots_u[3] = 0.2; // decreasing
    s.knots_u[4] = 0.1;
    o.shape = SurfaceObject{s};
    History h;
    const auto st = h.execute(doc, add_object(o));
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().code, ErrorCode::knots);
    EXPECT_EQ(st.error().path.rfind("/shape/knots/0", 0), 0u) << st.error().path;
    ImplicitObject f;
    f.expression = "x";
    f.cell = 0;
    o.shape = f;
    expect_refused(doc, add_object(o), ErrorCode::schema, "/shape/cell");
    f.cell = 0.1;
    f.parameter_names = {"x"};
    f.parameter_values = {1};
    o.shape = f;
    expect_refused(doc, add_object(o), ErrorCode::schema, "/shape/parameters/0/name");
    f.parameter_names = {"a"};
    f.parameter_values = {};
    o.shape = f;
    expect_refused(doc, add_object(o), ErrorCode::schema, "/shape/parameters");
    f.parameter_values = {1};
    f.lo.y = 2;
    o.shape = f;
    expect_refused(doc, add_object(o), ErrorCode::schema, "/shape/bounds/1/1");
}

TEST(ObjectCommands, RemoveRestoresPositionAndSelection) {
    Document doc = sample_document();
    doc.view.selection = Selection{grid_id, 1, 2};
    History h;
    const Document before = doc;
    ASSERT_TRUE(h.execute(doc, remove_object(grid_id)).ok());
    EXPECT_EQ(doc.find(grid_id), nullptr);
    EXPECT_EQ(doc.view.selection, Selection{});
    EXPECT_EQ(h.undo_label(), "Delete grid");
    h.undo(doc);
    EXPECT_TRUE(same_document(doc, before));
    EXPECT_EQ(doc.index_of(grid_id), 2);
    expect_undo_redo_exact(doc, remove_object(hill_id));
    expect_refused(doc, remove_object(42), ErrorCode::schema, "/id");
}

TEST(ObjectCommands, Rename) {
    Document doc = sample_document();
    const Document after = expect_undo_redo_exact(doc, rename_object(hill_id, "Mont Blanc"));
    EXPECT_EQ(after.find(hill_id)->name, "Mont Blanc");
    expect_refused(doc, rename_object(hill_id, ""), ErrorCode::schema, "/name");
    expect_refused(doc, rename_object(7, "x"), ErrorCode::schema, "/id");
}

TEST(ObjectCommands, HideAndShow) {
    Document doc = sample_document();
    const Document hidden = expect_undo_redo_exact(doc, set_visible(hill_id, false));
    EXPECT_FALSE(hidden.find(hill_id)->visible);
    Document again = hidden;
    const Document shown = expect_undo_redo_exact(again, set_visible(hill_id, true));
    EXPECT_TRUE(shown.find(hill_id)->visible);
    expect_refused(doc, set_visible(7, false), ErrorCode::schema, "/id");
}

TEST(ObjectCommands, ReplaceShape) {
    Document doc = sample_document();
    doc.view.selection = Selection{hill_id, 4, 4};
    geom::Surface s = make_planar_grid(3, 3, 2, 2, geom::SplineType::bspline);
    const Document after =
        expect_undo_redo_exact(doc, edit_shape(hill_id, SurfaceObject{s}, "Make B-spline"));
    // P44 no longer exists: the object stays selected without a point.
    EXPECT_EQ(after.view.selection, (Selection{hill_id, -1, -1}));
    History h;
    ASSERT_TRUE(h.execute(doc, edit_shape(hill_id, SurfaceObject{s}, "Make B-spline")).ok());
    EXPECT_EQ(h.undo_label(), "Make B-spline");
    s.n_u = 4; // inconsistent with the points
    expect_refused(doc, edit_shape(hill_id, SurfaceObject{s}, "x"), ErrorCode::schema,
                   "/shape/points");
}

TEST(SetColors, UndoRedoMergeAndRefusal) {
    Document doc = sample_document();
    Colors c = doc.colors;
    c.background = {0, 0, 0, 1};
    expect_undo_redo_exact(doc, set_colors(c));
    History h;
    ASSERT_TRUE(h.execute(doc, set_colors(c)).ok());
    c.surface.r = 0.5f;
    ASSERT_TRUE(h.execute(doc, set_colors(c)).ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(h.undo_label(), "Change colours");
    c.indicator.g = 1.5f;
    expect_refused(doc, set_colors(c), ErrorCode::schema, "/indicator/1");
    c.indicator.g = std::nanf("");
    expect_refused(doc, set_colors(c), ErrorCode::schema, "/indicator/1");
}

} // namespace
