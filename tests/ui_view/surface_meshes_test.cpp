// The surfaces' display meshes (ui/view/surface_meshes): made once, changed in place by a
// drag (only the touched rows, the same vertices a full remake gives), remade whole when the
// analysis kind changes, dropped when a surface is no longer drawn.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/knots.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trimmed_tessellator.hpp"
#include "ui/view/mesh_data.hpp"
#include "ui/view/surface_meshes.hpp"
#include "ui/view/tessellation_sampling.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

geom::Surface bicubic(int n) {
    geom::Surface s;
    s.type = geom::SplineType::bspline;
    s.degree_u = s.degree_v = 3;
    s.n_u = s.n_v = n;
    s.knots_u = s.knots_v = geom::clamped_uniform_knots(n, 3);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) s.points.push_back({double(i), double(j), 0.1 * i * j});
    s.weights.assign(s.points.size(), 1.0);
    return s;
}

std::vector<SurfaceDraw> draw_of(const geom::Surface& s) {
    SurfaceDraw d;
    d.id = 7;
    d.surface = &s;
    d.density = 8;
    return {d};
}

} // namespace

TEST(SurfaceMeshes, ADragChangesOnlyTheTouchedRowsAndMatchesAFullRemake) {
    geom::Surface s = bicubic(12);
    SurfaceMeshes meshes;
    std::vector<SurfaceDraw> draws = draw_of(s);
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 1);
    const SurfaceMesh* m = draws[0].display;
    ASSERT_NE(m, nullptr);
    const std::uint64_t first = m->revision;
    EXPECT_NE(first, 0u);
    EXPECT_FALSE(m->partial);
    EXPECT_EQ(draws[0].mesh_revision, first);
    EXPECT_EQ(m->vertices.size(), m->mesh.mesh().positions.size() * floats_per_vertex);
    EXPECT_FALSE(m->wire_pairs.empty());

    draws = draw_of(s); // unchanged: nothing to do
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 0);
    EXPECT_EQ(draws[0].display->revision, first);

    s.points[static_cast<std::size_t>(5 * 12 + 6)].z += 0.5; // one point of a 12 x 12 net
    draws = draw_of(s);
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 1);
    m = draws[0].display;
    EXPECT_TRUE(m->partial);
    EXPECT_EQ(m->since, first);
    EXPECT_GT(m->revision, first);
    EXPECT_LT(m->count, m->mesh.mesh().positions.size());

    SurfaceMeshes fresh;
    std::vector<SurfaceDraw> again = draw_of(s);
    fresh.update(again, AnalysisKind::off);
    EXPECT_EQ(again[0].display->vertices, m->vertices);
}

TEST(SurfaceMeshes, AnAnalysisKindRemakesWholeAndAnUndrawnSurfaceIsDropped) {
    const geom::Surface s = bicubic(6);
    SurfaceMeshes meshes;
    std::vector<SurfaceDraw> draws = draw_of(s);
    meshes.update(draws, AnalysisKind::off);
    const std::uint64_t before = draws[0].display->revision;
    draws = draw_of(s);
    EXPECT_EQ(meshes.update(draws, AnalysisKind::mean), 1);
    EXPECT_FALSE(draws[0].display->partial);
    EXPECT_EQ(draws[0].display->scalar_kind, AnalysisKind::mean);
    EXPECT_NE(draws[0].display->revision, before);
    // Zebra stripes come from the normals: remade without the scalar.
    draws = draw_of(s);
    EXPECT_EQ(meshes.update(draws, AnalysisKind::zebra), 1);
    EXPECT_EQ(draws[0].display->scalar_kind, AnalysisKind::off);

    std::vector<SurfaceDraw> none;
    meshes.update(none, AnalysisKind::off); // not drawn this frame: dropped
    draws = draw_of(s);
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 1);
    EXPECT_FALSE(draws[0].display->partial);
}

TEST(SurfaceMeshes, AGestureDrawsTheCoarseGridAndTheStillFrameTheFullOneAgain) {
    geom::Surface s = bicubic(8); // 5 spans a side
    SurfaceMeshes meshes;
    std::vector<SurfaceDraw> draws = draw_of(s);
    draws[0].density = 32;
    meshes.update(draws, AnalysisKind::off);
    const auto full = display_samples(s, 32);
    EXPECT_EQ(draws[0].display->mesh.samples_u(), full.first);
    // A drag on a CPU rasteriser: the coarse grid, remade whole (its triangles too).
    s.points[static_cast<std::size_t>(4 * 8 + 4)].z += 0.5;
    std::vector<SurfaceDraw> gesture = draw_of(s);
    gesture[0].density = 32;
    EXPECT_EQ(meshes.update(gesture, AnalysisKind::off, /*gesture=*/true), 1);
    const SurfaceMesh* m = gesture[0].display;
    EXPECT_EQ(m->mesh.samples_u(), 5 * gesture_density + 1);
    EXPECT_EQ(m->mesh.samples_v(), 5 * gesture_density + 1);
    EXPECT_FALSE(m->partial);
    EXPECT_EQ(m->mesh.mesh().triangles.size(), 2u * (5 * gesture_density) * (5 * gesture_density));
    // The next gesture frame moves rows of the coarse grid only.
    s.points[static_cast<std::size_t>(4 * 8 + 4)].z += 0.5;
    gesture = draw_of(s);
    gesture[0].density = 32;
    EXPECT_EQ(meshes.update(gesture, AnalysisKind::off, true), 1);
    EXPECT_TRUE(gesture[0].display->partial);
    // Released: the full grid again, the same vertices a fresh mesh has.
    draws = draw_of(s);
    draws[0].density = 32;
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 1);
    EXPECT_FALSE(draws[0].display->partial);
    SurfaceMeshes fresh;
    std::vector<SurfaceDraw> again = draw_of(s);
    again[0].density = 32;
    fresh.update(again, AnalysisKind::off);
    EXPECT_EQ(draws[0].display->vertices, again[0].display->vertices);
    EXPECT_EQ(draws[0].display->wire_pairs, again[0].display->wire_pairs);
}

namespace {

// bicubic(n)'s domain [0, 1]^2 less a round hole in the middle.
geom::Trim round_hole() {
    geom::Trim t;
    t.holes.push_back(geom::circle_loop({0.5, 0.5}, 0.25, /*clockwise=*/true).value());
    return t;
}

} // namespace

TEST(SurfaceMeshes, ATrimmedSurfaceDrawsTheTrimmedTessellatorsMesh) {
    geom::Surface s = bicubic(8);
    const geom::Trim trim = round_hole();
    SurfaceMeshes meshes;
    std::vector<SurfaceDraw> draws = draw_of(s);
    draws[0].trim = &trim;
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 1);
    const SurfaceMesh* m = draws[0].display;
    ASSERT_NE(m, nullptr);
    ASSERT_TRUE(m->trimmed.has_value());
    // The mesh drawn is the trimmed tessellator's at the same sampling, bit for bit.
    const geom::Mesh expected =
        geom::tessellate_trimmed(s, trim, m->trimmed->samples_u, m->trimmed->samples_v);
    EXPECT_EQ(m->geometry().positions, expected.positions);
    EXPECT_EQ(m->geometry().triangles, expected.triangles);
    EXPECT_EQ(m->vertices.size(), expected.positions.size() * floats_per_vertex);
    EXPECT_FALSE(m->wire_pairs.empty());
    // No vertex inside the hole (the loop's own points lie on the circle).
    const geom::TrimmedLayout& layout = m->trimmed->tessellator->layout();
    for (std::uint32_t k = 0; k < layout.vertex_count(); ++k) {
        const glm::dvec2 p = layout.param(k);
        EXPECT_GT(std::hypot(p.x - 0.5, p.y - 0.5), 0.25 - 1e-3) << p.x << ", " << p.y;
    }
    // Unchanged: nothing to do; a moved point: remade whole, the triangulation kept.
    draws = draw_of(s);
    draws[0].trim = &trim;
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 0);
    const auto* layout_before = &m->trimmed->tessellator->layout();
    s.points[10].z += 0.5;
    draws = draw_of(s);
    draws[0].trim = &trim;
    EXPECT_EQ(meshes.update(draws, AnalysisKind::mean), 1);
    m = draws[0].display;
    EXPECT_FALSE(m->partial);
    EXPECT_EQ(&m->trimmed->tessellator->layout(), layout_before);
    EXPECT_EQ(
        m->geometry().positions,
        geom::tessellate_trimmed(s, trim, m->trimmed->samples_u, m->trimmed->samples_v).positions);
    // The trim removed: the grid mesh again.
    draws = draw_of(s);
    EXPECT_EQ(meshes.update(draws, AnalysisKind::off), 1);
    EXPECT_FALSE(draws[0].display->trimmed.has_value());
    EXPECT_EQ(draws[0].display->geometry().positions.size(),
              draws[0].display->mesh.mesh().positions.size());
}
