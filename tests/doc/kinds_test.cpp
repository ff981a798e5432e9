// Object kinds: every kind answers the document's questions (core/doc/kinds), transforms move
// every kind that has control points (a triangle too), and every refusal names the object's
// real kind.
#include <gtest/gtest.h>

#include <functional>
#include <glm/gtc/matrix_transform.hpp>

#include "core/doc/commands_curve.hpp"
#include "core/doc/commands_multires.hpp"
#include "core/doc/placement.hpp"
#include "tests/doc/doc_fixtures.hpp"

namespace isoparm::doc {
namespace {

using namespace testing;

TEST(Kinds, EveryKindNamesItselfInASentence) {
    EXPECT_EQ(kind_noun(ObjectKind::surface), "a surface");
    EXPECT_EQ(kind_noun(ObjectKind::curve), "a curve");
    EXPECT_EQ(kind_noun(ObjectKind::implicit), "an implicit surface");
    EXPECT_EQ(kind_noun(ObjectKind::triangle), "a triangular patch");
    EXPECT_EQ(kind_file_noun(ObjectKind::implicit), "an implicit");
    EXPECT_EQ(kind_file_noun(ObjectKind::triangle), "a triangle");
    for (const Object& o : sample_document_with_triangle().objects)
        EXPECT_EQ(static_cast<int>(o.kind()), static_cast<int>(o.shape.index())) << o.name;
}

TEST(Kinds, ControlPointsAndTheirNamesComeFromEachKind) {
    const Document doc = sample_document_with_triangle();
    const Shape& hill = doc.find(hill_id)->shape;
    const Shape& curve = doc.find(curve_id)->shape;
    const Shape& ball = doc.find(ball_id)->shape;
    const Shape& tri = doc.find(tri_id)->shape;
    EXPECT_EQ(control_points_of(hill).size(), 25u);
    EXPECT_EQ(control_points_of(curve).size(), 7u);
    EXPECT_TRUE(control_points_of(ball).empty());
    EXPECT_EQ(control_points_of(tri).size(), 10u);
    EXPECT_EQ(control_weights_of(tri).size(), 10u);
    EXPECT_TRUE(has_control_point(hill, 4, 4));
    EXPECT_FALSE(has_control_point(hill, 4, -1));
    EXPECT_TRUE(has_control_point(curve, 6, -1));
    EXPECT_FALSE(has_control_point(curve, 6, 0));
    EXPECT_FALSE(has_control_point(ball, 0, 0));
    EXPECT_TRUE(has_control_point(tri, 1, 2));
    EXPECT_FALSE(has_control_point(tri, 2, 2));
    EXPECT_EQ(point_label_of(hill, PointName::position, 2, 3), "P23");
    EXPECT_EQ(point_label_of(hill, PointName::weight, 12, 3), "w12,3");
    EXPECT_EQ(point_label_of(curve, PointName::position, 4, 0), "P4");
    EXPECT_EQ(point_label_of(tri, PointName::position, 2, 1), "b210");
    EXPECT_EQ(point_label_of(tri, PointName::weight, 0, 1), "w012");
    EXPECT_EQ(point_label_of(tri, PointName::indexed, 1, 0), "b1,0,2");
    EXPECT_EQ(point_label_of(hill, PointName::indexed, 2, 2), "P2,2");
    // The implicit surface's box, the others' control points.
    const auto box = bounds_of(ball);
    ASSERT_TRUE(box);
    EXPECT_EQ(box->lo, glm::dvec3(-1, -1, -1.5));
    EXPECT_EQ(bounds_of(tri)->lo.z, 0.0);
    EXPECT_EQ(bounds_of(tri)->hi.z, 1.5);
}

// The 3D view's Move and Rotate are transform_object: a triangular patch moves and rotates
// with them, exactly and undoably, as surfaces and curves do.
TEST(Kinds, ATriangleMovesAndRotatesWithTransformObject) {
    Document doc = sample_document_with_triangle();
    const geom::TrianglePatch before = *doc.find(tri_id)->triangle();
    const glm::dvec3 d(0.5, -2, 0.25);
    const Document moved =
        expect_undo_redo_exact(doc, transform_object(tri_id, glm::translate(glm::dmat4(1.0), d)));
    const geom::TrianglePatch& t = *moved.find(tri_id)->triangle();
    ASSERT_EQ(t.points.size(), before.points.size());
    for (std::size_t k = 0; k < t.points.size(); ++k) EXPECT_EQ(t.points[k], before.points[k] + d);
    EXPECT_EQ(t.weights, before.weights);
    // Affine invariance (Farin 17.1): the rotated patch is the patch rotated, weights and all
    // (the document holds the moved patch now).
    const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), 0.7, glm::dvec3(0, 0, 1));
    const Document turned = expect_undo_redo_exact(doc, transform_object(tri_id, r));
    const geom::TrianglePatch& u = *turned.find(tri_id)->triangle();
    for (const geom::Barycentric& at :
         {geom::Barycentric{0.2, 0.3, 0.5}, geom::Barycentric{0.6, 0.1, 0.3}}) {
        const auto p = geom::triangle_point(t, at), q = geom::triangle_point(u, at);
        ASSERT_TRUE(p && q);
        EXPECT_LT(glm::length(glm::dvec3(r * glm::dvec4(*p, 1)) - *q), 1e-12);
    }
}

// A kind without control points cannot be transformed, and the refusal says what it is.
TEST(Kinds, AnImplicitSurfaceIsRefusedATransformAsWhatItIs) {
    Document doc = sample_document_with_triangle();
    const auto st = transform_object(ball_id, glm::dmat4(1.0))->check(doc);
    ASSERT_FALSE(st.ok());
    EXPECT_EQ(st.error().path, "/id");
    EXPECT_EQ(st.error().message,
              "object 'ball' is an implicit surface; it has no control points to transform");
}

// Every command that serves some kinds refuses the others naming the object's own kind
// ("object 'tri' is a triangular patch; ..."), never another kind's.
TEST(Kinds, EveryRefusalNamesTheObjectsRealKind) {
    using Make = std::function<std::unique_ptr<Command>(std::uint64_t)>;
    const std::vector<std::pair<const char*, Make>> commands = {
        {"move_knot", [](std::uint64_t id) { return move_knot_run(id, geom::Dir::u, 4, 1, 0.3); }},
        {"insert_knot", [](std::uint64_t id) { return insert_knot(id, geom::Dir::u, 0.3); }},
        {"elevate_degree", [](std::uint64_t id) { return elevate_degree(id, geom::Dir::u); }},
        {"split", [](std::uint64_t id) { return split_object(id, geom::Dir::u, 0.3); }},
        {"remove_knot",
         [](std::uint64_t id) { return remove_knot(id, geom::Dir::u, 0.25, 1, 1e-9); }},
        {"convert",
         [](std::uint64_t id) { return convert_object(id, geom::SplineType::bspline, false); }},
        {"transform", [](std::uint64_t id) { return transform_object(id, glm::dmat4(1.0)); }},
        {"edit_point",
         [](std::uint64_t id) {
             return edit_point({id, 0, 0, glm::dvec3(0), std::nullopt});
         }},
        {"multires_edit",
         [](std::uint64_t id) {
             MultiresEditSpec s;
             s.id = id;
             s.detail_scale = 0.5;
             return multires_edit(s);
         }},
        {"split_triangle",
         [](std::uint64_t id) {
             return split_triangle(id, {0.2, 0.3, 0.5});
         }},
        {"set_curve_degree", [](std::uint64_t id) { return set_curve_degree(id, 2); }},
    };
    const Document doc = sample_document_with_triangle();
    int refusals = 0;
    for (const Object& o : doc.objects) {
        const std::string own = kind_noun(o.kind());
        for (const auto& [name, make] : commands) {
            const auto st = make(o.id)->check(doc);
            if (st.ok() || st.error().path != "/id") continue;
            const std::string& m = st.error().message;
            const std::string prefix = "object '" + o.name + "' is ";
            if (m.rfind(prefix, 0) != 0) continue; // not a refusal of the kind
            ++refusals;
            // The kind named right after "is ", and only it: "is a triangular patch;".
            EXPECT_EQ(m.substr(prefix.size(), own.size() + 1), own + ";") << name << ": " << m;
        }
    }
    // Each kind is refused by several commands (the triangle by knot moves and inserts,
    // conversion, multiresolution, the curve designer; the implicit by all that need points).
    EXPECT_GE(refusals, 20);
}

} // namespace
} // namespace isoparm::doc
