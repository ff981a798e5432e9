// Every kind of object in scene files and exports (core/scene on the kinds' facts in
// core/doc/kinds): each kind's members round-trip exactly, refusals name the value and list
// what a table accepts, selections follow each kind's control points, exports take each kind's
// own form.
#include <gtest/gtest.h>

#include "core/doc/commands_curve.hpp"
#include "core/scene/export_document.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/doc/doc_fixtures.hpp"

namespace isoparm::doc {
namespace {

using namespace testing;
using geom::ErrorCode;

TEST(KindsIo, EveryKindsShapeRoundTripsThroughItsJsonForm) {
    const Document doc = sample_document_with_triangle();
    for (const Object& o : doc.objects) {
        const nlohmann::json j = scene::shape_to_json(o.shape);
        EXPECT_EQ(j.at("kind"), geom::name_of(o.kind())) << o.name;
        // The geometry is under a member named as the kind.
        EXPECT_TRUE(j.contains(geom::name_of(o.kind()))) << j.dump();
        auto back = scene::shape_from_json(j, "/shape");
        ASSERT_TRUE(back.ok()) << o.name << ": " << back.error().message;
        Object copy = o;
        copy.shape = *back;
        EXPECT_TRUE(same_object(copy, o)) << o.name;
        auto object = scene::object_from_json(scene::object_to_json(o), "/objects/0");
        ASSERT_TRUE(object.ok()) << object.error().message;
        EXPECT_TRUE(same_object(*object, o)) << o.name;
    }
}

TEST(KindsIo, EachKindAllowsItsOwnMembersAndNamesItselfInTheRefusal) {
    const Document doc = sample_document_with_triangle();
    auto with = [&](std::uint64_t id, const char* member) {
        nlohmann::json j = scene::object_to_json(*doc.find(id));
        j[member] = 1;
        return scene::object_from_json(j, "/objects/2");
    };
    auto tri = with(tri_id, "plane");
    ASSERT_FALSE(tri.ok());
    EXPECT_EQ(tri.error().path, "/objects/2/plane");
    EXPECT_EQ(tri.error().message,
              "unknown member 'plane' in a triangle object (allowed: id, name, "
              "kind, visible, triangle)");
    auto ball = with(ball_id, "patch_group");
    ASSERT_FALSE(ball.ok());
    EXPECT_NE(ball.error().message.find("in an implicit object"), std::string::npos);
    // A surface may be a subpatch (patch_group), a curve may not; both may be constructed.
    EXPECT_NE(with(curve_id, "patch_group")
                  .error()
                  .message.find(
                      "(allowed: id, name, kind, visible, plane, knot_mode, curve, construction)"),
              std::string::npos);
    EXPECT_TRUE(with(hill_id, "patch_group").ok());
    nlohmann::json shape = scene::shape_to_json(doc.find(hill_id)->shape);
    shape["kind"] = "tetrahedron";
    auto unknown = scene::shape_from_json(shape, "/shape");
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().path, "/shape/kind");
    EXPECT_EQ(unknown.error().message,
              "kind must be surface, curve, implicit or triangle, got 'tetrahedron'");
    shape = scene::shape_to_json(doc.find(tri_id)->shape);
    shape.erase("triangle");
    auto missing = scene::shape_from_json(shape, "/shape");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().path, "/shape/triangle");
}

TEST(KindsIo, ASelectedPointIsReadAsItsKindNamesItsPoints) {
    nlohmann::json j = scene::scene_to_json(sample_document_with_triangle());
    auto select = [&](std::uint64_t id, nlohmann::json point) {
        nlohmann::json s = j;
        s["selection"] = {{"object", id}, {"point", point}};
        return scene::scene_from_json(s);
    };
    EXPECT_TRUE(select(hill_id, {4, 4}).ok());
    EXPECT_TRUE(select(curve_id, {6}).ok());
    EXPECT_TRUE(select(tri_id, {1, 2}).ok());
    EXPECT_EQ(select(hill_id, {4}).error().message, "a surface's selected point is [i, j]");
    EXPECT_EQ(select(curve_id, {1, 1}).error().message, "a curve's selected point is [i]");
    EXPECT_EQ(select(curve_id, {7}).error().path, "/selection/point/0");
    EXPECT_EQ(select(ball_id, {0, 0}).error().message,
              "an implicit surface has no control points to select");
    EXPECT_EQ(select(tri_id, {3, 1}).error().path, "/selection/point/1");
}

TEST(KindsIo, ExportsTakeEachKindsOwnFormAndSkipTheRestSayingWhy) {
    const Document doc = sample_document_with_triangle();
    std::vector<const Object*> all;
    for (const Object& o : doc.objects) all.push_back(&o);
    scene::ExportOptions exact;
    exact.format = scene::ExportFormat::obj;
    auto r = scene::export_document(all, exact);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->skipped.size(), 2u);
    EXPECT_EQ(r->skipped[0], "'ball' (id 5): an implicit surface has no exact form (export a mesh: "
                             "STL, PLY, glTF or OBJ mesh)");
    EXPECT_NE(r->skipped[1].find("'tri' (id 6): IGES, STEP and OBJ free-form have no triangular"),
              std::string::npos);
    scene::ExportOptions mesh;
    mesh.format = scene::ExportFormat::ply;
    mesh.samples = 4;
    r = scene::export_document(all, mesh);
    ASSERT_TRUE(r.ok()) << r.error().message;
    ASSERT_EQ(r->skipped.size(), 1u);
    EXPECT_EQ(r->skipped[0],
              "'profile' (id 2): a curve has no mesh (export IGES, STEP or OBJ free-form)");
}

TEST(TriangleObject, SceneRoundTripKeepsTheTriangleTheSelectionAndTheIndicator) {
    Document doc = sample_document_with_triangle();
    doc.view.selection = Selection{tri_id, 0, 2};
    doc.view.barycentric = {0.125, 0.625, 0.25};
    auto back = scene::scene_from_text(scene::scene_to_text(doc));
    ASSERT_TRUE(back.ok()) << back.error().message << " at " << back.error().path;
    EXPECT_TRUE(same_document(doc, *back));
    // A scene without a triangle does not write the triangle indicator.
    EXPECT_EQ(scene::scene_to_json(sample_document()).count("barycentric"), 0u);
}

TEST(TriangleObject, SceneRefusalsNameTheValue) {
    nlohmann::json j = scene::scene_to_json(sample_document_with_triangle());
    nlohmann::json bad = j;
    bad["selection"] = {{"object", tri_id}, {"point", {2, 2}}};
    auto r = scene::scene_from_json(bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/selection/point/1");
    bad = j;
    bad["barycentric"] = {0.5, 0.5, 0.25};
    r = scene::scene_from_json(bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/barycentric");
    bad = j;
    bad["objects"][5]["triangle"]["points"].erase(0);
    r = scene::scene_from_json(bad);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/objects/5/triangle/points");
}

TEST(TriangleObject, MeshExportTessellatesTheTriangleAndExactFormatsSkipIt) {
    const Document doc = sample_document_with_triangle();
    const std::vector<const Object*> objects{doc.find(tri_id)};
    scene::ExportOptions mesh;
    mesh.format = scene::ExportFormat::obj_mesh;
    mesh.samples = 5;
    auto r = scene::export_document(objects, mesh);
    ASSERT_TRUE(r.ok()) << r.error().message;
    const std::string text(r->bytes.begin(), r->bytes.end());
    int faces = 0;
    for (std::size_t at = text.find("\nf "); at != std::string::npos;
         at = text.find("\nf ", at + 1))
        ++faces;
    EXPECT_EQ(faces, 16); // (samples - 1)^2
    scene::ExportOptions iges;
    iges.format = scene::ExportFormat::iges;
    auto refused = scene::export_document(objects, iges);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("triangular Bezier patch"), std::string::npos);
}

TEST(CurveScene, KnotModeRoundTripsAndOldScenesLoadAsCustom) {
    Document doc = sample_document();
    auto designed = new_curve_object("wave", CurvePlane::xy,
                                     {{0, 0, 0}, {1, 1, 0}, {2, -1, 0}, {3, 2, 0}, {4, 0, 0}}, 3,
                                     CurveKnotMode::centripetal);
    ASSERT_TRUE(designed.ok());
    designed->id = doc.allocate_id();
    doc.objects.push_back(*designed);
    const std::string text = scene::scene_to_text(doc);
    EXPECT_NE(text.find("\"knot_mode\": \"centripetal\""), std::string::npos);
    auto back = scene::scene_from_text(text);
    ASSERT_TRUE(back.ok()) << back.error().message;
    EXPECT_TRUE(same_document(*back, doc));
    // Custom is the default and not written: the sample curve's object has no knot_mode.
    const std::string custom_text = scene::scene_to_text(sample_document());
    EXPECT_EQ(custom_text.find("knot_mode"), std::string::npos);
    auto old = scene::scene_from_text(custom_text);
    ASSERT_TRUE(old.ok());
    EXPECT_EQ(old->find(curve_id)->curve_object()->knot_mode, CurveKnotMode::custom);
    std::string bad = text;
    bad.replace(bad.find("centripetal"), 11, "zigzag");
    auto refused = scene::scene_from_text(bad);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().code, ErrorCode::schema);
    EXPECT_EQ(refused.error().path, "/objects/5/knot_mode");
    EXPECT_NE(refused.error().message.find("zigzag"), std::string::npos);
}

TEST(Patches, SceneKeepsGroupsAndContinuity) {
    PaperSplit p;
    p.doc.continuity = Continuity::c1;
    auto text = scene::scene_to_text(p.doc);
    auto back = scene::scene_from_text(text);
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_TRUE(same_document(*back, p.doc));

    // Overlapping patches load (a scene must always load back); the first one in the
    // objects list holds the overlap.
    Document overlapping = p.doc;
    overlapping.objects.push_back(overlapping.objects[0]);
    overlapping.objects.back().id = overlapping.allocate_id();
    overlapping.objects.back().name = "copy";
    auto loaded = scene::scene_from_text(scene::scene_to_text(overlapping));
    ASSERT_TRUE(loaded) << loaded.error().message;
    EXPECT_EQ(patch_at(*loaded, loaded->objects[0].patch_group, {0.1, 0.1}), loaded->objects[0].id);

    // A curve cannot be a subpatch.
    Document curve = p.doc;
    Object c;
    c.id = curve.allocate_id();
    c.name = "profile";
    c.patch_group = curve.objects[0].patch_group;
    geom::Curve line;
    line.type = geom::SplineType::bspline;
    line.degree = 1;
    line.knots = {0, 0, 1, 1};
    line.points = {{0, 0, 0}, {1, 0, 0}};
    line.weights = {1, 1};
    c.shape = CurveObject{line, CurvePlane::xy};
    curve.objects.push_back(c);
    auto r = scene::scene_from_text(scene::scene_to_text(curve));
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().path, "/objects/3/patch_group");

    auto unknown = scene::scene_from_text(
        R"({"format": "isoparm-scene", "version": 1, "objects": [], "continuity": "C2"})");
    ASSERT_FALSE(unknown);
    EXPECT_EQ(unknown.error().path, "/continuity");
}

} // namespace
} // namespace isoparm::doc
