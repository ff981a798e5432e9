// Many points at once: a row scaled about its centroid, a selection mirrored, a drag of a
// selection merged into one step, rows and columns, exact quarter turns and mirror partners.
#include <gtest/gtest.h>

#include "core/doc/commands_points.hpp"
#include "core/doc/point_set.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::ErrorCode;

namespace {

TEST(PointSet, RowsColumnsAndAll) {
    const Document doc = sample_document_with_triangle();
    const Shape& grid = doc.find(grid_id)->shape; // 4 x 5
    EXPECT_EQ(all_points(grid).size(), 20u);
    EXPECT_EQ(row_points(grid, 1),
              (std::vector<PointIndex>{{1, 0}, {1, 1}, {1, 2}, {1, 3}, {1, 4}}));
    EXPECT_EQ(column_points(grid, 4), (std::vector<PointIndex>{{0, 4}, {1, 4}, {2, 4}, {3, 4}}));
    EXPECT_TRUE(row_points(grid, 4).empty());
    const Shape& curve = doc.find(curve_id)->shape;
    EXPECT_EQ(all_points(curve).size(), 7u);
    EXPECT_EQ(row_points(curve, 0).front(), (PointIndex{0, -1}));
    EXPECT_EQ(all_points(doc.find(tri_id)->shape).size(), 10u);
    EXPECT_TRUE(all_points(doc.find(ball_id)->shape).empty());
}

TEST(PointSet, QuarterTurnsAreExactAndMirrorsFlipOneAxis) {
    const glm::dvec3 p(1, 2, 3);
    EXPECT_EQ(apply_affine(rotation(2, 90), p), glm::dvec3(-2, 1, 3));
    EXPECT_EQ(apply_affine(rotation(2, -90), p), glm::dvec3(2, -1, 3));
    EXPECT_EQ(apply_affine(rotation(0, 180), p), glm::dvec3(1, -2, -3));
    EXPECT_EQ(apply_affine(rotation(1, 90), p), glm::dvec3(3, 2, -1)); // z turns towards x
    const glm::dvec3 r = apply_affine(rotation(2, 30), glm::dvec3(1, 0, 0));
    EXPECT_NEAR(r.x, std::sqrt(3.0) / 2, 1e-15);
    EXPECT_NEAR(r.y, 0.5, 1e-15);
    EXPECT_EQ(apply_affine(mirror(1), p), glm::dvec3(1, -2, 3));
    EXPECT_EQ(apply_affine(about(scaling({2, 2, 2}), {1, 1, 1}), p), glm::dvec3(1, 3, 5));
}

TEST(PointsCommands, ScalingASelectedRowByTwoAboutItsCentroid) {
    Document doc = sample_document();
    const geom::Surface before = surface_of(doc, hill_id); // the default 5 x 5 hill
    const std::vector<PointIndex> row = row_points(doc.find(hill_id)->shape, 2);
    const glm::dvec3 c = centroid(doc.find(hill_id)->shape, row);
    const Document after = expect_undo_redo_exact(
        doc, transform_points({hill_id, row, scaling({2, 2, 2}), Pivot::centroid, {}, ""}));
    const geom::Surface& s = surface_of(after, hill_id);
    for (int j = 0; j < 5; ++j) {
        // p -> c + 2 (p - c): every coordinate's distance from the centroid doubles.
        const glm::dvec3 want = c + 2.0 * (before.point(2, j) - c);
        for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(s.point(2, j)[a], want[a]) << j;
        for (int i : {0, 1, 3, 4}) EXPECT_EQ(s.point(i, j), before.point(i, j));
    }
    // The centroid stays where it was.
    const glm::dvec3 c2 = centroid(after.find(hill_id)->shape, row);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(c2[a], c[a], 1e-15);
}

TEST(PointsCommands, ARowOfAFlatGridScaledByTwoGivesTheExpectedPoints) {
    // The planar 5 x 5 grid on [-1, 1]^2: row 1 is x = -0.5, y = -1 .. 1, z = 0; its
    // centroid is (-0.5, 0, 0); scaled by 2 it runs y = -2 .. 2 at x = -0.5.
    Document doc = default_document();
    Object grid;
    grid.id = doc.allocate_id();
    grid.name = "grid";
    grid.shape = SurfaceObject{make_planar_grid(5, 5, 3, 3, geom::SplineType::bspline)};
    doc.objects.push_back(grid);
    History h;
    ASSERT_TRUE(
        h.execute(
             doc,
             transform_points(
                 {grid.id, row_points(grid.shape, 1), scaling({2, 2, 2}), Pivot::centroid, {}, ""}))
            .ok());
    const geom::Surface& s = surface_of(doc, grid.id);
    const double ys[5] = {-2, -1, 0, 1, 2};
    for (int j = 0; j < 5; ++j) EXPECT_EQ(s.point(1, j), glm::dvec3(-0.5, ys[j], 0)) << j;
    EXPECT_EQ(h.undo_label(), "Transform 5 points");
}

TEST(PointsCommands, MirroringASelection) {
    Document doc = sample_document();
    const geom::Curve before = curve_of(doc, curve_id);
    // Points 1 and 2 of the profile mirrored in the plane x = 0.5: x -> 1 - x.
    const Document after = expect_undo_redo_exact(doc, transform_points({curve_id,
                                                                         {{1, -1}, {2, -1}},
                                                                         mirror(0),
                                                                         Pivot::point,
                                                                         glm::dvec3(0.5, 0, 0),
                                                                         "Mirror"}));
    const geom::Curve& c = curve_of(after, curve_id);
    EXPECT_EQ(c.points[1], glm::dvec3(0, 2, 0));    // (1, 2, 0)
    EXPECT_EQ(c.points[2], glm::dvec3(-1, 2.5, 0)); // (2, 2.5, 0)
    EXPECT_EQ(c.points[0], before.points[0]);
    EXPECT_EQ(c.weights, before.weights);
    // And about the origin, in y = 0: the whole grid's points flip their y.
    Document d2 = sample_document();
    const geom::Surface g = surface_of(d2, grid_id);
    History h;
    ASSERT_TRUE(
        h.execute(
             d2,
             transform_points(
                 {grid_id, all_points(d2.find(grid_id)->shape), mirror(1), Pivot::origin, {}, ""}))
            .ok());
    for (int i = 0; i < g.n_u; ++i)
        for (int j = 0; j < g.n_v; ++j) {
            const glm::dvec3 p = g.point(i, j);
            EXPECT_EQ(surface_of(d2, grid_id).point(i, j), glm::dvec3(p.x, -p.y, p.z));
        }
}

TEST(PointsCommands, ADragOfASelectionIsOneUndoStepWithTheFinalPositions) {
    Document doc = sample_document();
    History h;
    const Document before = doc;
    const std::vector<PointIndex> pts{{0, 0}, {4, 4}};
    for (int k = 1; k <= 4; ++k)
        ASSERT_TRUE(
            h.execute(doc, move_points({hill_id, pts, {{0, 0, 0.1 * k}, {1, 1, -0.1 * k}}, ""}))
                .ok());
    EXPECT_EQ(h.size(), 1u);
    EXPECT_EQ(surface_of(doc, hill_id).point(4, 4), glm::dvec3(1, 1, -0.4));
    const std::optional<CommandSpec> top = h.top()->spec();
    ASSERT_TRUE(top.has_value());
    const auto* spec = std::get_if<MovePointsSpec>(&*top);
    ASSERT_TRUE(spec);
    EXPECT_EQ(spec->positions[0], glm::dvec3(0, 0, 0.4));
    ASSERT_TRUE(h.undo(doc));
    EXPECT_TRUE(same_document(doc, before));
}

TEST(PointsCommands, RefusalsNameTheValue) {
    Document doc = sample_document_with_triangle();
    expect_refused(doc, move_points({hill_id, {}, {}, ""}), ErrorCode::schema, "/points");
    expect_refused(doc, move_points({hill_id, {{0, 0}, {5, 0}}, {{0, 0, 0}, {0, 0, 0}}, ""}),
                   ErrorCode::schema, "/points/1");
    expect_refused(doc, move_points({hill_id, {{0, 0}, {0, 0}}, {{0, 0, 0}, {0, 0, 0}}, ""}),
                   ErrorCode::schema, "/points/1");
    expect_refused(doc, move_points({hill_id, {{0, 0}}, {}, ""}), ErrorCode::schema, "/positions");
    expect_refused(doc, move_points({ball_id, {{0, 0}}, {{0, 0, 0}}, ""}), ErrorCode::schema,
                   "/id");
    glm::dmat4 projective(1.0);
    projective[0][3] = 1;
    expect_refused(doc, transform_points({hill_id, {{0, 0}}, projective, Pivot::origin, {}, ""}),
                   ErrorCode::schema, "/matrix");
    // A triangle's points move too.
    expect_undo_redo_exact(
        doc, transform_points(
                 {tri_id, {{1, 1}, {3, 0}}, translation({0, 0, 1}), Pivot::origin, {}, ""}));
}

TEST(PointSet, MirrorPartnersOfASymmetricNet) {
    // The flat 5 x 5 grid on [-1, 1]^2: x = -1 .. 1 along i, y along j.
    const Shape grid = SurfaceObject{make_planar_grid(5, 5, 3, 3, geom::SplineType::bspline)};
    EXPECT_EQ(mirror_partner(grid, {1, 4}, 0), (PointIndex{3, 4})); // x = 0
    EXPECT_EQ(mirror_partner(grid, {0, 1}, 1), (PointIndex{0, 3})); // y = 0
    EXPECT_EQ(mirror_partner(grid, {2, 2}, 0), (PointIndex{2, 2})); // on the plane: itself
    EXPECT_EQ(mirror_partner(grid, {1, 1}, 2), (PointIndex{1, 1})); // z = 0: every point
    // The sample curve is not symmetric about x = 0.
    EXPECT_FALSE(mirror_partner(sample_document().find(curve_id)->shape, {1, -1}, 0).has_value());
}

TEST(PointSet, ASymmetricMoveMovesTheMirrorPartner) {
    const Shape grid = SurfaceObject{make_planar_grid(5, 5, 3, 3, geom::SplineType::bspline)};
    // P11 = (-0.5, -0.5, 0) raised and pulled in x: its partner about x = 0 is P31.
    SymmetricMove m = symmetric_move(grid, {{1, 1}}, {{-0.6, -0.5, 0.7}}, 0);
    ASSERT_EQ(m.points.size(), 2u);
    EXPECT_EQ(m.partners, 1);
    EXPECT_EQ(m.points[1], (PointIndex{3, 1}));
    EXPECT_EQ(m.positions[1], glm::dvec3(0.6, -0.5, 0.7));
    // A point on the plane x = 0 stays on it.
    SymmetricMove c = symmetric_move(grid, {{2, 1}}, {{0.2, -0.5, 0.7}}, 0);
    ASSERT_EQ(c.points.size(), 1u);
    EXPECT_EQ(c.positions[0], glm::dvec3(0, -0.5, 0.7));
    // Both partners moved by the user: each keeps its own position.
    SymmetricMove b = symmetric_move(grid, {{1, 1}, {3, 1}}, {{-1, 0, 0}, {2, 0, 0}}, 0);
    EXPECT_EQ(b.points.size(), 2u);
    EXPECT_EQ(b.positions[1], glm::dvec3(2, 0, 0));
    // As one command: both points move, one undo step.
    Document doc = default_document();
    Object o;
    o.id = doc.allocate_id();
    o.name = "grid";
    o.shape = grid;
    doc.objects.push_back(o);
    History h;
    ASSERT_TRUE(h.execute(doc, move_points({o.id, m.points, m.positions, ""})).ok());
    EXPECT_EQ(surface_of(doc, o.id).point(3, 1), glm::dvec3(0.6, -0.5, 0.7));
    EXPECT_EQ(h.size(), 1u);
}

} // namespace
