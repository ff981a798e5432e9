// A scene's objects as an exchange file (core/scene/export_document): the format from the
// extension, which objects are chosen, what each format skips, and the refusals.
#include <gtest/gtest.h>

#include "core/exchange/mesh_weld.hpp"
#include "core/geom/construct.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/scene/export_document.hpp"

namespace {

using namespace isoparm;
using scene::ExportFormat;

doc::Object object(std::uint64_t id, std::string name, doc::Shape shape, bool visible = true) {
    doc::Object o;
    o.id = id;
    o.name = std::move(name);
    o.shape = std::move(shape);
    o.visible = visible;
    return o;
}

doc::Document scene_with_everything() {
    doc::Document d;
    const auto circle = geom::full_circle({3, 0, 0}, 1, geom::Plane::xz);
    d.objects.push_back(object(1, "torus", doc::SurfaceObject{*geom::revolve(*circle, 360)}));
    d.objects.push_back(object(2, "rim", doc::CurveObject{*circle}));
    doc::ImplicitObject ball;
    ball.expression = "x^2 + y^2 + z^2 - 0.5";
    ball.cell = 0.1;
    d.objects.push_back(object(3, "ball", ball));
    d.objects.push_back(object(4, "rim", doc::CurveObject{*circle}, false));
    d.objects.push_back(object(5, "hidden", doc::CurveObject{*circle}, false));
    return d;
}

TEST(ExportDocument, TheFormatComesFromTheExtensionInAnyCase) {
    EXPECT_EQ(scene::export_format_for("a/b.STEP", false), ExportFormat::step);
    EXPECT_EQ(scene::export_format_for("b.stp", false), ExportFormat::step);
    EXPECT_EQ(scene::export_format_for("b.Igs", false), ExportFormat::iges);
    EXPECT_EQ(scene::export_format_for("b.iges", false), ExportFormat::iges);
    EXPECT_EQ(scene::export_format_for("b.obj", false), ExportFormat::obj);
    EXPECT_EQ(scene::export_format_for("b.obj", true), ExportFormat::obj_mesh);
    EXPECT_EQ(scene::export_format_for("b.stl", true), ExportFormat::stl);
    EXPECT_EQ(scene::export_format_for("b.glb", false), ExportFormat::glb);
    EXPECT_EQ(scene::export_format_for("b.stp", true), std::nullopt); // --mesh with an exact one
    EXPECT_EQ(scene::export_format_for("b.dwg", false), std::nullopt);
    EXPECT_EQ(scene::export_format_for("dir.stl/file", false), std::nullopt);
}

TEST(ExportDocument, VisibleObjectsOrOneByIdOrName) {
    const doc::Document d = scene_with_everything();
    const auto all = scene::export_objects(d, "");
    ASSERT_TRUE(all);
    EXPECT_EQ(all->size(), 3u); // the hidden ones are left out
    const auto by_id = scene::export_objects(d, "5");
    ASSERT_TRUE(by_id);
    EXPECT_EQ((*by_id)[0]->name, "hidden"); // a hidden object can be named
    const auto by_name = scene::export_objects(d, "ball");
    ASSERT_TRUE(by_name);
    EXPECT_EQ((*by_name)[0]->id, 3u);
    const auto twice = scene::export_objects(d, "rim");
    ASSERT_FALSE(twice);
    EXPECT_NE(twice.error().message.find("2 objects are named 'rim' (ids 2, 4)"), std::string::npos)
        << twice.error().message;
    const auto none = scene::export_objects(d, "hat");
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().message.find("no object has the id or name 'hat'"), std::string::npos);
    EXPECT_FALSE(scene::export_objects(doc::Document{}, ""));
}

TEST(ExportDocument, EachFormatTakesWhatItCanHoldAndSaysWhatItSkipped) {
    const doc::Document d = scene_with_everything();
    const auto objects = *scene::export_objects(d, "");
    scene::ExportOptions options;
    options.name = "all";
    options.format = ExportFormat::step;
    const auto step = scene::export_document(objects, options);
    ASSERT_TRUE(step) << step.error().message;
    ASSERT_EQ(step->skipped.size(), 1u);
    EXPECT_NE(step->skipped[0].find("'ball' (id 3): an implicit surface has no exact form"),
              std::string::npos);
    EXPECT_NE(step->bytes.find("ADVANCED_FACE"), std::string::npos);
    EXPECT_NE(step->bytes.find("GEOMETRIC_CURVE_SET"), std::string::npos);

    options.format = ExportFormat::stl;
    options.samples = 9;
    const auto stl = scene::export_document(objects, options);
    ASSERT_TRUE(stl) << stl.error().message;
    ASSERT_EQ(stl->skipped.size(), 1u);
    EXPECT_NE(stl->skipped[0].find("'rim' (id 2): a curve has no mesh"), std::string::npos);
    // The torus: 8 x 8 cells of 2 triangles, welded (no triangle lost), and the ball.
    std::uint32_t count = 0;
    for (int k = 0; k < 4; ++k)
        count |= std::uint32_t(static_cast<unsigned char>(stl->bytes[80 + k])) << (8 * k);
    EXPECT_GT(count, 128u);

    options.samples = 1;
    EXPECT_FALSE(scene::export_document(objects, options));
    options.samples = 1001;
    EXPECT_FALSE(scene::export_document(objects, options));

    // Nothing left: an error that says why.
    const std::vector<const doc::Object*> curve_only = {&d.objects[1]};
    options.samples = 8;
    const auto nothing = scene::export_document(curve_only, options);
    ASSERT_FALSE(nothing);
    EXPECT_NE(nothing.error().message.find("nothing to write as binary STL"), std::string::npos);
}

TEST(ExportDocument, NonPositiveWeightsAreRefusedByIgesAndStepOnly) {
    doc::Document d = scene_with_everything();
    geom::Surface& torus = *d.objects[0].surface();
    torus.weight(3, 4) = 0;
    const std::vector<const doc::Object*> objects = {&d.objects[0]};
    scene::ExportOptions options;
    for (ExportFormat f : {ExportFormat::iges, ExportFormat::step}) {
        options.format = f;
        const auto r = scene::export_document(objects, options);
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, geom::ErrorCode::weights);
        EXPECT_NE(r.error().message.find("'torus' (id 1): weight 0 of control point (3, 4)"),
                  std::string::npos)
            << r.error().message;
        EXPECT_NE(r.error().message.find("export a mesh instead"), std::string::npos);
    }
    for (ExportFormat f : {ExportFormat::obj, ExportFormat::ply, ExportFormat::glb}) {
        options.format = f;
        EXPECT_TRUE(scene::export_document(objects, options));
    }
}

} // namespace

namespace {

// A trimmed surface exports as itself: its trimmed face in IGES and STEP (the hole an inner
// bound), its trimmed mesh in the mesh formats.
TEST(ExportDocument, ATrimmedSurfaceExportsItsTrimmedFaceAndMesh) {
    doc::Document d;
    doc::SurfaceObject plate{doc::make_planar_grid(4, 4, 3, 3, geom::SplineType::bspline), {}};
    d.objects.push_back(object(1, "plate", plate));
    const auto objects = *scene::export_objects(d, "");
    scene::ExportOptions options;
    options.name = "plate";
    options.format = ExportFormat::step;
    const auto plain = scene::export_document(objects, options);
    options.format = ExportFormat::stl;
    options.samples = 16;
    const auto plain_stl = scene::export_document(objects, options);
    ASSERT_TRUE(plain && plain_stl);
    EXPECT_EQ(plain->bytes.find("FACE_BOUND("), std::string::npos);

    std::get<doc::SurfaceObject>(d.objects[0].shape)
        .trim.holes.push_back(geom::circle_loop({0.5, 0.5}, 0.25, /*clockwise=*/true).value());
    options.format = ExportFormat::step;
    const auto trimmed = scene::export_document(objects, options);
    ASSERT_TRUE(trimmed) << trimmed.error().message;
    EXPECT_NE(trimmed->bytes.find("FACE_BOUND("), std::string::npos);
    EXPECT_NE(trimmed->bytes.find("PCURVE"), std::string::npos);
    options.format = ExportFormat::iges;
    const auto iges = scene::export_document(objects, options);
    ASSERT_TRUE(iges) << iges.error().message;
    EXPECT_NE(iges->bytes.find("     144"), std::string::npos); // a trimmed surface entity
    options.format = ExportFormat::stl;
    const auto stl = scene::export_document(objects, options);
    ASSERT_TRUE(stl) << stl.error().message;
    EXPECT_NE(stl->bytes.size(), plain_stl->bytes.size());
}

} // namespace
