// Each kind's view answers (ui/view/kinds): the editor it opens, how its points are indexed,
// its Kind label, its control net, and what it adds to the 3D view's batches.
#include <gtest/gtest.h>

#include "core/doc/commands_triangle.hpp"
#include "core/geom/trim/trim.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/scene_builder.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

doc::Object object_with(doc::Shape shape, std::uint64_t id = 1) {
    doc::Object o;
    o.id = id;
    o.shape = std::move(shape);
    return o;
}

geom::Surface grid(int nu, int nv) {
    geom::Surface s;
    s.type = geom::SplineType::bezier;
    s.degree_u = nu - 1;
    s.degree_v = nv - 1;
    s.n_u = nu;
    s.n_v = nv;
    s.knots_u = geom::Knots(static_cast<std::size_t>(nu), 0.0);
    s.knots_u.resize(static_cast<std::size_t>(2 * nu), 1.0);
    s.knots_v = geom::Knots(static_cast<std::size_t>(nv), 0.0);
    s.knots_v.resize(static_cast<std::size_t>(2 * nv), 1.0);
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) s.points.push_back({double(i), double(j), 0.0});
    s.weights.assign(s.points.size(), 1.0);
    return s;
}

geom::Curve polygon(int n) {
    geom::Curve c;
    c.type = geom::SplineType::bezier;
    c.degree = n - 1;
    c.knots = geom::Knots(static_cast<std::size_t>(n), 0.0);
    c.knots.resize(static_cast<std::size_t>(2 * n), 1.0);
    for (int i = 0; i < n; ++i) c.points.push_back({double(i), double(i % 2), 0.0});
    c.weights.assign(static_cast<std::size_t>(n), 1.0);
    return c;
}

struct Batches {
    std::vector<SurfaceDraw> surfaces;
    LineBatch net, knots, knots_double, knots_full, curves, box;
    PointBatch points;
    SceneBatches refs{surfaces, net, knots, knots_double, knots_full, curves, box, points};
};

} // namespace

TEST(KindView, EachKindOpensItsEditorAndIndexesItsPoints) {
    const doc::Object s = object_with(doc::SurfaceObject{grid(3, 4)});
    const doc::Object c = object_with(doc::CurveObject{polygon(4)});
    const doc::Object f = object_with(doc::ImplicitObject{});
    const doc::Object t =
        object_with(doc::TriangleObject{doc::make_flat_triangle(2, false).value()});
    EXPECT_EQ(editor_of(s), ObjectEditor::control_points);
    EXPECT_EQ(editor_of(c), ObjectEditor::curve_designer);
    EXPECT_EQ(editor_of(f), ObjectEditor::implicit_surface);
    EXPECT_EQ(editor_of(t), ObjectEditor::control_points);
    EXPECT_TRUE(two_index_points(s.shape));
    EXPECT_FALSE(two_index_points(c.shape));
    EXPECT_FALSE(two_index_points(f.shape));
    EXPECT_TRUE(two_index_points(t.shape));
    EXPECT_STREQ(kind_label(s), geom::name_of(geom::SplineType::bezier));
    EXPECT_STREQ(kind_label(c), "curve");
    EXPECT_STREQ(kind_label(f), "implicit");
    EXPECT_STREQ(kind_label(t), "triangle");
    EXPECT_STREQ(traits_of(s.shape).note, "");
    EXPECT_EQ(control_net_of(c).points.size(), 4u);
    EXPECT_EQ(control_net_of(c).find(2, -1), 2);
    EXPECT_TRUE(control_net_of(f).points.empty());
}

// The Objects tab says which surfaces are trimmed (the Kind column: "bezier, trimmed").
TEST(KindView, ATrimmedSurfaceSaysSoInItsKindNote) {
    doc::SurfaceObject trimmed{grid(3, 3)};
    trimmed.trim.holes.push_back(*geom::circle_loop({0.5, 0.5}, 0.2, true));
    EXPECT_STREQ(traits_of(doc::Shape{trimmed}).note, "trimmed");
    EXPECT_STREQ(traits_of(doc::Shape{trimmed}).label, geom::name_of(geom::SplineType::bezier));
    trimmed.trim = {};
    EXPECT_STREQ(traits_of(doc::Shape{trimmed}).note, "");
}

TEST(KindView, EachKindDrawsItsOwnPartOfTheScene) {
    const doc::Colors colors;
    ObjectLook look;
    look.colors = &colors;
    look.own.control_points = look.own.control_net = true;
    look.own.knot_curves = false;
    look.selected = true;
    look.point_i = 1;
    look.point_j = 2;

    Batches surface;
    draw_in_scene(object_with(doc::SurfaceObject{grid(3, 4)}), look, surface.refs);
    ASSERT_EQ(surface.surfaces.size(), 1u);
    EXPECT_NE(surface.surfaces[0].surface, nullptr);
    EXPECT_EQ(surface.points.points.size(), 11u); // 12 points, the selected one drawn apart
    EXPECT_EQ(surface.net.vertices.size(), 2u * (3 * 3 + 2 * 4)); // 17 segments
    EXPECT_TRUE(surface.curves.vertices.empty());

    Batches curve;
    look.point_j = -1;
    draw_in_scene(object_with(doc::CurveObject{polygon(4)}), look, curve.refs);
    EXPECT_TRUE(curve.surfaces.empty());
    EXPECT_FALSE(curve.curves.vertices.empty());
    EXPECT_EQ(curve.points.points.size(), 3u);

    // An implicit surface without a mesh yet: only its box, when selected.
    Batches implicit;
    draw_in_scene(object_with(doc::ImplicitObject{}), look, implicit.refs);
    EXPECT_TRUE(implicit.surfaces.empty());
    EXPECT_EQ(implicit.box.vertices.size(), 24u);
    EXPECT_TRUE(implicit.points.points.empty());

    Batches triangle;
    look.point_i = 0;
    look.point_j = 0;
    draw_in_scene(object_with(doc::TriangleObject{doc::make_flat_triangle(2, false).value()}), look,
                  triangle.refs);
    EXPECT_TRUE(triangle.surfaces.empty()); // no mesh cache given
    EXPECT_EQ(triangle.points.points.size(), 5u);
    EXPECT_FALSE(triangle.net.vertices.empty());
}
