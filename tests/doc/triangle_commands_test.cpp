// Triangular patches as document objects: control points and weights through edit_point,
// degree elevation, the split at a point, the scene file and mesh export.
#include <gtest/gtest.h>

#include <cmath>

#include "core/doc/commands_triangle.hpp"
#include "core/geom/triangle.hpp"
#include "tests/doc/doc_fixtures.hpp"

namespace isoparm::doc {
namespace {

using namespace testing;

const geom::TrianglePatch& triangle_in(const Document& doc, std::uint64_t id) {
    return *doc.find(id)->triangle();
}

// The patch evaluated at the barycentric points (i, j, k) / 7, i + j + k = 7.
std::vector<glm::dvec3> sampled(const geom::TrianglePatch& t) {
    std::vector<glm::dvec3> out;
    for (int i = 0; i <= 7; ++i)
        for (int j = 0; i + j <= 7; ++j) {
            const auto p = geom::triangle_point(t, {i / 7.0, j / 7.0, (7 - i - j) / 7.0});
            out.push_back(p.value_or(glm::dvec3(NAN)));
        }
    return out;
}

double largest_distance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    double d = 0;
    for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, glm::length(a[k] - b[k]));
    return d;
}

TEST(TriangleObject, NewFlatTriangleHasItsCornersAndRefusesADegreeOutOfRange) {
    const geom::TrianglePatch t = make_flat_triangle(4, false).value();
    EXPECT_EQ(t.points.size(), 15u);
    EXPECT_EQ(t.points[geom::TrianglePatch::index(4, 4, 0)], glm::dvec3(2, 0, 0));
    // Every point lies in z = 0 at its own domain position, so the patch is the flat triangle.
    const auto p = geom::triangle_point(t, {0.2, 0.3, 0.5}).value();
    const glm::dvec3 want = 0.2 * t.points[0] +
                            0.3 * t.points[geom::TrianglePatch::index(4, 0, 4)] +
                            0.5 * t.points.back();
    EXPECT_LT(glm::length(p - want), 1e-15);
    EXPECT_EQ(make_flat_triangle(0, false).error().path, "/degree");
    EXPECT_EQ(make_flat_triangle(max_new_triangle_degree + 1, true).error().path, "/degree");
}

TEST(TriangleObject, EditPointMovesBijkAndItsWeightExactlyUndoably) {
    Document doc = sample_document_with_triangle();
    const Document after = expect_undo_redo_exact(
        doc, edit_point(EditPointSpec{tri_id, 1, 2, glm::dvec3(0.5, 0.25, -1), -3.0}));
    const geom::TrianglePatch& t = triangle_in(after, tri_id);
    const int at = geom::TrianglePatch::index(3, 1, 2);
    EXPECT_EQ(t.points[at], glm::dvec3(0.5, 0.25, -1));
    EXPECT_EQ(t.weights[at], -3.0);
    auto move = move_control_point(tri_id, 1, 1, glm::dvec3(0, 0, 2));
    EXPECT_TRUE(move->apply(doc).ok());
    EXPECT_EQ(move->label(), "Move b111");
}

TEST(TriangleObject, PointRefusalsNameTheIndexAndTheWeight) {
    Document doc = sample_document_with_triangle();
    expect_refused(doc, move_control_point(tri_id, 4, 0, glm::dvec3(0)), geom::ErrorCode::schema,
                   "/i");
    expect_refused(doc, move_control_point(tri_id, 2, 2, glm::dvec3(0)), geom::ErrorCode::schema,
                   "/j");
    expect_refused(doc, move_control_point(tri_id, 1, -1, glm::dvec3(0)), geom::ErrorCode::schema,
                   "/j");
    // A non-rational triangle keeps unit weights.
    Object flat{0, "flat", TriangleObject{make_flat_triangle(2, false).value()}};
    ASSERT_TRUE(add_object(flat)->apply(doc).ok());
    const std::uint64_t flat_id = doc.objects.back().id;
    auto refused = set_weight(flat_id, 0, 1, 2.0);
    const auto st = refused->apply(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path, "/weight");
    EXPECT_NE(st.error().message.find("w011 = 2"), std::string::npos) << st.error().message;
}

TEST(TriangleObject, ElevationKeepsTheShapeAndTheSelectedPoint) {
    Document doc = sample_document_with_triangle();
    doc.view.selection = Selection{tri_id, 1, 1};
    const std::vector<glm::dvec3> before = sampled(triangle_in(doc, tri_id));
    const Document after = expect_undo_redo_exact(doc, elevate_degree(tri_id, geom::Dir::u, 2));
    const geom::TrianglePatch& t = triangle_in(after, tri_id);
    EXPECT_EQ(t.degree, 5);
    EXPECT_LT(largest_distance(sampled(t), before), 1e-13);
    // b111 of the cubic sits at (1/3, 1/3, 1/3): in the quintic the nearest are b221, b212 and
    // b122, each index 1 or 2.
    const Selection& sel = after.view.selection;
    EXPECT_EQ(sel.object, tri_id);
    const int k = 5 - sel.i - sel.j;
    EXPECT_TRUE(sel.i >= 1 && sel.i <= 2 && sel.j >= 1 && sel.j <= 2 && k >= 1 && k <= 2)
        << sel.i << " " << sel.j;
    Document refuse = sample_document_with_triangle();
    expect_refused(refuse, elevate_degree(tri_id, geom::Dir::u, 0), geom::ErrorCode::schema,
                   "/times");
    expect_refused(refuse, elevate_degree(tri_id, geom::Dir::u, geom::max_triangle_degree),
                   geom::ErrorCode::limit, "/times");
}

TEST(TriangleObject, KnotEditsAndConversionRefuseATriangleNamingIt) {
    Document doc = sample_document_with_triangle();
    expect_refused(doc, insert_knot(tri_id, geom::Dir::u, 0.5), geom::ErrorCode::schema, "/id");
    expect_refused(doc, split_object(tri_id, geom::Dir::u, 0.5), geom::ErrorCode::schema, "/id");
    expect_refused(doc, convert_object(tri_id, geom::SplineType::nurbs), geom::ErrorCode::schema,
                   "/id");
}

TEST(TriangleObject, SplitGivesThreePiecesThatCoverTheShapeAndUndoesExactly) {
    Document doc = sample_document_with_triangle();
    doc.view.selection = Selection{tri_id, 3, 0}; // b300, the corner piece 2 keeps
    const geom::TrianglePatch original = triangle_in(doc, tri_id);
    const geom::Barycentric at{0.2, 0.3, 0.5};
    const std::size_t count = doc.objects.size();
    const Document after = expect_undo_redo_exact(doc, split_triangle(tri_id, at));
    ASSERT_EQ(after.objects.size(), count + 2);
    const std::size_t first = after.objects.size() - 3;
    for (int v = 0; v < 3; ++v) {
        const Object& piece = after.objects[first + v];
        EXPECT_EQ(piece.name, "tri." + std::to_string(v + 1));
        ASSERT_NE(piece.triangle(), nullptr);
        // A point of piece v with local coordinates a is the original's point at
        // a_v * at + sum_{w != v} a_w e_w.
        for (const geom::Barycentric a :
             {geom::Barycentric{0.5, 0.25, 0.25}, geom::Barycentric{0.1, 0.1, 0.8}}) {
            geom::Barycentric q{};
            for (int w = 0; w < 3; ++w) q[w] = (w == v ? 0.0 : a[w]) + a[v] * at[w];
            const glm::dvec3 p = geom::triangle_point(*piece.triangle(), a).value();
            const glm::dvec3 want = geom::triangle_point(original, q).value();
            EXPECT_LT(glm::length(p - want), 1e-12) << "piece " << v;
        }
    }
    // b300 is vertex 0: pieces 1 and 2 keep it, and the first of them holds the selection.
    EXPECT_EQ(after.view.selection.object, after.objects[first + 1].id);
    EXPECT_EQ(after.view.selection.i, 3);
    EXPECT_EQ(after.view.selection.j, 0);
}

TEST(TriangleObject, SplitRefusesAPointNotStrictlyInsideAndAnotherKind) {
    Document doc = sample_document_with_triangle();
    expect_refused(doc, split_triangle(tri_id, {0.5, 0.5, 0}), geom::ErrorCode::domain, "/param");
    expect_refused(doc, split_triangle(tri_id, {0.5, 0.5, 0.5}), geom::ErrorCode::domain, "/param");
    expect_refused(doc, split_triangle(tri_id, {NAN, 0.5, 0.5}), geom::ErrorCode::schema,
                   "/param/0");
    expect_refused(doc, split_triangle(hill_id, {0.2, 0.3, 0.5}), geom::ErrorCode::schema, "/id");
}

} // namespace
} // namespace isoparm::doc
