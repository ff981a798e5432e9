// The renderer's inputs built from a document: sampling policy, wireframe indices, change
// detection, overlay contents.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/doc/commands.hpp"
#include "core/doc/document.hpp"
#include "core/doc/placement.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/mesh_data.hpp"
#include "ui/view/scene_builder.hpp"
#include "ui/view/tessellation_sampling.hpp"

using namespace isoparm;
using namespace isoparm::ui;

TEST(Sampling, DensityPerSpanWithinTheBudget) {
    const geom::Surface small =
        doc::make_planar_grid(5, 5, 3, 3, geom::SplineType::nurbs); // 2 spans
    EXPECT_EQ(display_samples(small, 32), (std::pair<int, int>{65, 65}));
    const geom::Surface big =
        doc::make_planar_grid(32, 32, 3, 3, geom::SplineType::nurbs); // 29 spans
    const auto [su, sv] = display_samples(big, 32);
    EXPECT_LE(static_cast<long>(su) * sv, max_display_vertices);
    EXPECT_GE(su, 100);
    EXPECT_EQ(su, sv);
    EXPECT_EQ(display_samples(small, 0), (std::pair<int, int>{5, 5})); // at least 2 per span
}

TEST(Sampling, GestureFramesTakeAtMostEightSamplesASpanAndTheirOwnBudget) {
    const geom::Surface small = doc::make_planar_grid(5, 5, 3, 3, geom::SplineType::nurbs);
    EXPECT_EQ(gesture_samples(small, 32), (std::pair<int, int>{17, 17}));
    EXPECT_EQ(gesture_samples(small, 4), display_samples(small, 4)); // never finer than still
    const geom::Surface big = doc::make_planar_grid(64, 64, 3, 3, geom::SplineType::nurbs);
    const auto [su, sv] = gesture_samples(big, 32);
    EXPECT_LE(static_cast<long>(su) * sv, max_gesture_vertices);
    EXPECT_GE(static_cast<long>(su) * sv, max_gesture_vertices * 9 / 10);
    EXPECT_LT(static_cast<long>(su) * sv,
              static_cast<long>(display_samples(big, 32).first) * display_samples(big, 32).second);
}

TEST(MeshData, SameSurfaceSeesEveryChange) {
    const geom::Surface a = doc::make_planar_grid(4, 4, 2, 2, geom::SplineType::nurbs);
    geom::Surface b = a;
    EXPECT_TRUE(same_surface(a, b));
    b.weight(1, 1) = 2;
    EXPECT_FALSE(same_surface(a, b));
    b = a;
    b.point(3, 0).z = 1e-300;
    EXPECT_FALSE(same_surface(a, b));
    b = a;
    b.knots_u[3] = std::nextafter(b.knots_u[3], 0.0);
    EXPECT_FALSE(same_surface(a, b));
}

TEST(MeshData, SameBasisIgnoresOnlyThePointsPositions) {
    const geom::Surface a = doc::make_planar_grid(4, 4, 2, 2, geom::SplineType::nurbs);
    geom::Surface b = a;
    b.point(2, 1).z = 0.5; // a point's drag: R_ij stays
    EXPECT_TRUE(same_basis(a, b));
    b.weight(1, 1) = 2;
    EXPECT_FALSE(same_basis(a, b));
    b = a;
    b.knots_v[3] = std::nextafter(b.knots_v[3], 0.0);
    EXPECT_FALSE(same_basis(a, b));
    b = a;
    b.type = geom::SplineType::bspline;
    EXPECT_FALSE(same_basis(a, b));
}

TEST(MeshData, WireIndicesCoverBoundariesAndSkipMissingVertices) {
    // 3 x 3 grid, every line: 3 rows * 2 + 3 columns * 2 = 12 segments.
    EXPECT_EQ(wire_indices(3, 3, {}, 100).size(), 24u);
    // 65 x 65 with at most ~16 lines: the stride is 4, lines 0, 4, ..., 64.
    const auto w = wire_indices(65, 65, {}, 16);
    EXPECT_EQ(w.size(), 2u * (17 * 64) * 2);
    // A missing centre vertex removes the four segments touching it.
    std::vector<std::uint8_t> exists(9, 1);
    exists[4] = 0;
    EXPECT_EQ(wire_indices(3, 3, exists, 100).size(), 16u);
}

TEST(SceneBuilder, DefaultDocumentDrawsSurfaceNetPointsAndIndicator) {
    doc::Document d = doc::default_document();
    const BuiltScene scene = build_scene(d, {});
    ASSERT_EQ(scene.surfaces.size(), 1u);
    const geom::Surface* s = d.objects.front().surface();
    ASSERT_NE(s, nullptr);
    std::size_t points = 0, net_segments = 0;
    for (const PointBatch& b : scene.overlay.points) points += b.points.size();
    for (const LineBatch& l : scene.overlay.lines) net_segments += l.vertices.size() / 2;
    // Every control point plus S(u,v); at least the net's segments among the lines.
    EXPECT_EQ(points,
              static_cast<std::size_t>(s->n_u * s->n_v) + (d.view.display.indicator_point ? 1 : 0));
    EXPECT_GE(net_segments,
              static_cast<std::size_t>(s->n_u * (s->n_v - 1) + s->n_v * (s->n_u - 1)));
}

TEST(SceneBuilder, TogglesRemoveWhatTheyHide) {
    doc::Document d = doc::default_document();
    d.view.display.control_net = false;
    d.view.display.control_points = false;
    d.view.display.indicator_point = false;
    d.view.display.knot_curves = false;
    const BuiltScene scene = build_scene(d, {});
    EXPECT_TRUE(scene.overlay.points.empty());
    EXPECT_TRUE(scene.overlay.lines.empty());
    d.view.display.style = doc::DisplayStyle::wireframe;
    const BuiltScene wire = build_scene(d, {});
    EXPECT_FALSE(wire.surfaces.front().shaded);
    EXPECT_TRUE(wire.surfaces.front().wireframe);
}

TEST(SceneBuilder, IsoCurveLiesOnTheSurfaceEnds) {
    const doc::Document d = doc::default_document();
    const geom::Surface& s = *d.objects.front().surface();
    const auto pieces = iso_curve(s, geom::Dir::u, geom::domain(s, geom::Dir::u).lo, 11);
    ASSERT_EQ(pieces.size(), 1u);
    ASSERT_EQ(pieces[0].size(), 11u);
    // Clamped: the corner of the surface is the corner control point.
    const glm::dvec3 p00 = s.point(0, 0);
    EXPECT_NEAR(pieces[0].front().x, p00.x, 1e-5);
    EXPECT_NEAR(pieces[0].front().z, p00.z, 1e-5);
}

TEST(SceneBounds, CoversAllControlPoints) {
    const doc::Document d = doc::default_document();
    const auto box = doc::scene_bounds(d);
    ASSERT_TRUE(box.has_value());
    for (const glm::dvec3& p : d.objects.front().surface()->points)
        for (int k = 0; k < 3; ++k) {
            EXPECT_LE(box->lo[k], p[k]);
            EXPECT_GE(box->hi[k], p[k]);
        }
    EXPECT_FALSE(doc::scene_bounds(doc::Document{}).has_value());
}

TEST(KnotContinuityColor, EachOrderOfContinuityHasItsColour) {
    const glm::vec4 smooth(0.1f, 0.2f, 0.3f, 1);
    EXPECT_EQ(isoparm::ui::knot_continuity_color(3, 1, smooth), smooth);  // C2
    EXPECT_EQ(isoparm::ui::knot_continuity_color(3, 2, smooth).g, 0.85f); // C1 yellow
    EXPECT_EQ(isoparm::ui::knot_continuity_color(3, 3, smooth).g, 0.5f);  // C0 orange
    EXPECT_EQ(isoparm::ui::knot_continuity_color(2, 3, smooth).r, 0.95f); // C-1 red
}

TEST(SceneBuilder, BordersByContinuityDrawEachBorderInItsMeasuredColour) {
    doc::Document d = doc::default_document();
    doc::History h;
    const std::uint64_t id = d.objects.front().id;
    ASSERT_TRUE(h.execute(d, doc::split_object(id, geom::Dir::u, 0.5)).ok());
    SceneStyle style;
    const std::size_t plain = build_scene(d, style).overlay.lines.size();
    style.border_continuity = true;
    const BuiltScene scene = build_scene(d, style);
    ASSERT_EQ(scene.overlay.lines.size(), plain + 1);
    // A split is as smooth as the surface was: every segment of the border is cyan.
    const glm::vec4 cyan = border_level_color(doc::BorderLevel::g2);
    std::size_t found = 0;
    for (const LineBatch& b : scene.overlay.lines)
        for (const OverlayVertex& v : b.vertices) found += v.color == cyan;
    EXPECT_EQ(found, 2u * 64); // 65 samples along the one border
    EXPECT_NE(border_level_color(doc::BorderLevel::broken), cyan);
}

TEST(SceneBuilder, CurveGlyphsFollowTheSelectedCurve) {
    doc::Document d = doc::default_document();
    doc::Object o;
    o.name = "arc";
    o.shape = doc::CurveObject{*geom::circular_arc({0, 0, 0}, 2, 0, 180, geom::Plane::xy), {}, {}};
    doc::History h;
    ASSERT_TRUE(h.execute(d, doc::add_object(o)).ok());
    d.view.selection.object = d.objects.back().id;
    SceneStyle style;
    const std::size_t plain = build_scene(d, style).overlay.lines.size();
    style.curve_glyphs = {true, true, true};
    const BuiltScene scene = build_scene(d, style);
    // Teeth, their rim, the osculating circle and the frame.
    ASSERT_EQ(scene.overlay.lines.size(), plain + 4);
    // On a circle of radius 2 the osculating circle is the circle itself, and every tooth
    // lies on a ray from the centre with the same length.
    const CurveGlyphs g = curve_glyphs(*d.objects.back().curve(), 0.3, {true, true, true});
    ASSERT_TRUE(g.centre);
    EXPECT_LT(glm::length(*g.centre), 1e-12);
    for (const glm::dvec3& p : g.circle) EXPECT_NEAR(glm::length(p), 2, 1e-12);
    const double tooth = glm::distance(g.teeth.front().first, g.teeth.front().second);
    for (const auto& [base, tip] : g.teeth) {
        EXPECT_NEAR(glm::distance(base, tip), tooth, 1e-12);
        EXPECT_NEAR(glm::length(tip), 2 + tooth, 1e-12); // along -N: outside the arc
    }
    ASSERT_TRUE(g.tangent && g.normal && g.binormal);
    EXPECT_NEAR(std::abs(g.binormal->z), 1, 1e-12);
}
