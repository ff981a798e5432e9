// The document: lookup, exact comparison, the default scene and new planar grids.
#include <gtest/gtest.h>

#include "core/geom/evaluate.hpp"
#include "core/geom/validate.hpp"
#include "tests/doc/doc_fixtures.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::doc::testing;
using geom::ErrorCode;
using geom::SplineType;

namespace {

TEST(Document, FindAndIndexOf) {
    Document doc = sample_document();
    EXPECT_EQ(doc.find(grid_id)->name, "grid");
    EXPECT_EQ(std::as_const(doc).find(ball_id)->name, "ball");
    EXPECT_EQ(doc.find(0), nullptr);
    EXPECT_EQ(doc.find(77), nullptr);
    EXPECT_EQ(doc.index_of(patch_id), 3);
    EXPECT_EQ(doc.index_of(0), -1);
    EXPECT_EQ(doc.index_of(77), -1);
    EXPECT_EQ(doc.selected()->id, hill_id);
    EXPECT_EQ(doc.allocate_id(), 6u);
    EXPECT_EQ(doc.allocate_id(), 7u);
}

TEST(Document, DefaultSceneIsAShapedBicubicNurbs) {
    const Document doc = default_document();
    ASSERT_EQ(doc.objects.size(), 1u);
    const geom::Surface& s = surface_of(doc, doc.objects[0].id);
    EXPECT_TRUE(geom::validate_surface(s).ok());
    EXPECT_EQ(s.type, SplineType::nurbs);
    EXPECT_EQ(s.degree_u, 3);
    EXPECT_EQ(s.degree_v, 3);
    EXPECT_EQ(s.n_u, 5);
    EXPECT_EQ(s.n_v, 5);
    EXPECT_EQ(s.knots_u, (geom::Knots{0, 0, 0, 0, 0.5, 1, 1, 1, 1}));
    EXPECT_EQ(s.knots_v, s.knots_u);
    int non_unit = 0;
    for (double w : s.weights) non_unit += w != 1.0;
    EXPECT_GE(non_unit, 2);
    // Shaped: not flat, highest near the middle.
    const auto mid = geom::surface_point(s, 0.5, 0.5);
    const auto corner = geom::surface_point(s, 0.0, 0.0);
    ASSERT_TRUE(mid && corner);
    EXPECT_GT(mid->z, corner->z + 0.5);
    EXPECT_EQ(doc.view.selection.object, doc.objects[0].id);
    EXPECT_TRUE(doc.view.selection.has_point());
    EXPECT_EQ(doc.view.indicator, glm::dvec2(0.5, 0.5));
    EXPECT_GT(doc.next_id, doc.objects[0].id);
    EXPECT_TRUE(same_document(doc, default_document())); // deterministic
}

TEST(Document, SameGeometryComparesEveryField) {
    const Document base = sample_document();
    EXPECT_TRUE(same_geometry(base, sample_document()));
    auto differs = [&](auto change) {
        Document d = sample_document();
        change(d);
        return !same_geometry(base, d);
    };
    EXPECT_TRUE(differs([](Document& d) { d.objects[0].name = "x"; }));
    EXPECT_TRUE(differs([](Document& d) { d.objects[0].id = 9; }));
    EXPECT_TRUE(differs([](Document& d) { d.objects[0].visible = false; }));
    EXPECT_TRUE(differs([](Document& d) { std::swap(d.objects[0], d.objects[1]); }));
    EXPECT_TRUE(differs([](Document& d) { d.objects.pop_back(); }));
    EXPECT_TRUE(differs([](Document& d) {
        std::get<SurfaceObject>(d.objects[0].shape).surface.weights[0] = -1.0;
    }));
    EXPECT_TRUE(differs([](Document& d) {
        // 0.0 and -0.0 compare equal with ==, but not bit for bit.
        std::get<SurfaceObject>(d.objects[0].shape).surface.points[0].z = -0.0;
    }));
    EXPECT_TRUE(differs(
        [](Document& d) { std::get<SurfaceObject>(d.objects[0].shape).surface.knots_v[4] = 0.4; }));
    EXPECT_TRUE(differs([](Document& d) {
        std::get<SurfaceObject>(d.objects[0].shape).surface.type = SplineType::rational_bezier;
    }));
    EXPECT_TRUE(differs(
        [](Document& d) { std::get<CurveObject>(d.objects[1].shape).plane = CurvePlane::yz; }));
    EXPECT_TRUE(
        differs([](Document& d) { std::get<CurveObject>(d.objects[1].shape).curve.degree = 2; }));
    EXPECT_TRUE(differs([](Document& d) {
        std::get<ImplicitObject>(d.objects[4].shape).parameter_values[0] = 0.9;
    }));
    EXPECT_TRUE(differs(
        [](Document& d) { std::get<ImplicitObject>(d.objects[4].shape).expression = "x"; }));
    EXPECT_TRUE(
        differs([](Document& d) { std::get<ImplicitObject>(d.objects[4].shape).hi.z = 2; }));
    EXPECT_TRUE(differs([](Document& d) { d.colors.knot_curves.a = 0.5f; }));
    EXPECT_TRUE(differs([](Document& d) { d.colors.background.r = -0.0f; }));
    // View state is not geometry, but same_document sees it.
    Document d = sample_document();
    d.view.selection = Selection{};
    d.view.indicator.x = 0.25;
    d.view.display.knot_curves = true;
    EXPECT_TRUE(same_geometry(base, d));
    EXPECT_FALSE(same_document(base, d));
}

TEST(PlanarGrid, AllFourTypes) {
    for (SplineType t : {SplineType::bspline, SplineType::nurbs}) {
        const geom::Surface s = make_planar_grid(6, 4, 3, 2, t);
        EXPECT_TRUE(geom::validate_surface(s).ok());
        EXPECT_EQ(s.type, t);
        EXPECT_EQ(s.n_u, 6);
        EXPECT_EQ(s.n_v, 4);
        EXPECT_EQ(s.knots_u, geom::clamped_uniform_knots(6, 3));
        EXPECT_EQ(s.knots_v, geom::clamped_uniform_knots(4, 2));
        EXPECT_EQ(s.point(0, 0), glm::dvec3(-1, -1, 0));
        EXPECT_EQ(s.point(5, 3), glm::dvec3(1, 1, 0));
        for (double w : s.weights) EXPECT_EQ(w, 1.0);
        for (const auto& p : s.points) EXPECT_EQ(p.z, 0.0);
    }
    for (SplineType t : {SplineType::bezier, SplineType::rational_bezier}) {
        const geom::Surface s = make_planar_grid(4, 3, 3, 2, t);
        EXPECT_TRUE(geom::validate_surface(s).ok());
        EXPECT_EQ(s.knots_u, (geom::Knots{0, 0, 0, 0, 1, 1, 1, 1}));
        EXPECT_EQ(s.knots_v, (geom::Knots{0, 0, 0, 1, 1, 1}));
    }
    // The grid is symmetric about the origin.
    const geom::Surface s = make_planar_grid(4, 4, 1, 1, SplineType::bspline);
    EXPECT_EQ(s.point(1, 0).x, -s.point(2, 0).x);
}

TEST(PlanarGrid, CheckedVariantRefusesBadInput) {
    auto expect = [](geom::Expected<geom::Surface> r, ErrorCode code, const std::string& path) {
        ASSERT_FALSE(r.ok());
        EXPECT_EQ(r.error().code, code) << r.error().message;
        EXPECT_EQ(r.error().path, path) << r.error().message;
    };
    expect(make_planar_grid_checked(4, 4, 0, 2, SplineType::bspline), ErrorCode::degree,
           "/degree_u");
    expect(make_planar_grid_checked(4, 4, 2, -1, SplineType::bspline), ErrorCode::degree,
           "/degree_v");
    expect(make_planar_grid_checked(3, 4, 3, 2, SplineType::nurbs), ErrorCode::degree, "/rows");
    expect(make_planar_grid_checked(4, 2, 3, 2, SplineType::nurbs), ErrorCode::degree, "/cols");
    expect(make_planar_grid_checked(5, 3, 3, 2, SplineType::bezier), ErrorCode::degree, "/rows");
    expect(make_planar_grid_checked(4, 4, 3, 2, SplineType::rational_bezier), ErrorCode::degree,
           "/cols");
    expect(make_planar_grid_checked(5000, 4, 3, 2, SplineType::bspline), ErrorCode::limit, "/rows");
    expect(make_planar_grid_checked(2000, 2000, 3, 2, SplineType::bspline), ErrorCode::limit,
           "/cols");
    auto bez = make_planar_grid_checked(5, 3, 3, 2, SplineType::bezier);
    ASSERT_FALSE(bez.ok());
    EXPECT_NE(bez.error().message.find("Bezier"), std::string::npos) << bez.error().message;
    EXPECT_TRUE(make_planar_grid_checked(32, 32, 3, 3, SplineType::nurbs).ok());
}

} // namespace
