// The 3D view's drawing of a triangular patch: the mesh cache, the net, the indicator's
// isoparametric lines and de Casteljau's levels.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/doc/commands_triangle.hpp"
#include "core/doc/document.hpp"
#include "core/geom/triangle.hpp"
#include "ui/view/scene_builder.hpp"
#include "ui/view/triangle_meshes.hpp"
#include "ui/view/triangle_scene.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

geom::TrianglePatch bumped_cubic() {
    geom::TrianglePatch t = doc::make_flat_triangle(3, true).value();
    t.points[geom::TrianglePatch::index(3, 1, 1)].z = 2;
    t.weights[geom::TrianglePatch::index(3, 1, 1)] = 2;
    return t;
}

doc::Document triangle_document() {
    doc::Document d;
    d.objects.push_back(doc::Object{d.allocate_id(), "tri", doc::TriangleObject{bumped_cubic()}});
    d.view.selection = {1, 1, 1};
    d.view.barycentric = {0.2, 0.3, 0.5};
    return d;
}

double distance_to(const std::vector<glm::vec3>& line, const glm::vec3& p) {
    double best = INFINITY;
    for (const glm::vec3& q : line) best = std::min(best, static_cast<double>(glm::length(q - p)));
    return best;
}

} // namespace

TEST(TriangleScene, TheNetJoinsEveryPointToItsDomainNeighbours) {
    // Degree n: n rows of edges in each of the three directions, n (n + 1) / 2 each.
    for (int n = 1; n <= 5; ++n) {
        LineBatch net;
        add_triangle_net(net, doc::make_flat_triangle(n, false).value(), {1, 1, 1, 1});
        EXPECT_EQ(net.vertices.size(), 2u * 3 * n * (n + 1) / 2) << n;
        // On the flat triangle of side 2 sqrt(3) every edge is 2 sqrt(3) / n long.
        for (std::size_t k = 0; k < net.vertices.size(); k += 2)
            EXPECT_NEAR(glm::length(net.vertices[k].position - net.vertices[k + 1].position),
                        2 * std::sqrt(3.0) / n, 1e-5);
    }
}

TEST(TriangleScene, IsoLinesPassThroughTheIndicatorAndEndOnTheEdges) {
    const geom::TrianglePatch t = bumped_cubic();
    const geom::Barycentric p{0.2, 0.3, 0.5};
    const auto lines = triangle_iso_lines(t, p, 101);
    ASSERT_EQ(lines.size(), 3u);
    const glm::vec3 at(geom::triangle_point(t, p).value());
    for (int fixed = 0; fixed < 3; ++fixed) {
        // Sampled every 1/100 of the edge-to-edge run: the point lies within one step.
        EXPECT_LT(distance_to(lines[fixed], at), 0.08) << fixed;
        // Its ends: the other two coordinates zero in turn.
        geom::Barycentric end{};
        end[fixed] = p[fixed];
        end[(fixed + 2) % 3] = 1 - p[fixed];
        EXPECT_LT(
            glm::length(lines[fixed].front() - glm::vec3(geom::triangle_point(t, end).value())),
            1e-5);
    }
}

TEST(TriangleScene, DeCasteljauEndsAtThePatchPointAndShowsOneLevelPerStep) {
    const geom::TrianglePatch t = bumped_cubic();
    const geom::Barycentric p{0.2, 0.3, 0.5};
    Overlay all;
    add_triangle_de_casteljau(t, p, -1, 1, all);
    // The last batch is the result sphere, the patch point.
    ASSERT_FALSE(all.points.empty());
    const PointBatch& result = all.points.back();
    ASSERT_EQ(result.points.size(), 1u);
    EXPECT_LT(
        glm::length(result.points[0].position - glm::vec3(geom::triangle_point(t, p).value())),
        1e-5);
    // Step 1: level 1 (6 points of a quadratic net) in full, the control points faint.
    Overlay one;
    add_triangle_de_casteljau(t, p, 1, 1, one);
    std::size_t full = 0, faint = 0;
    for (const PointBatch& b : one.points)
        for (const OverlayVertex& v : b.points) (v.color.a < 1 ? faint : full) += 1;
    EXPECT_EQ(full, 6u);
    EXPECT_EQ(faint, 10u);
}

TEST(TriangleScene, MeshesAreCachedUntilThePatchChanges) {
    doc::Document d = triangle_document();
    TriangleMeshes meshes;
    meshes.update(d, 32);
    const TriangleMeshes::View first = meshes.view(1);
    ASSERT_NE(first.mesh, nullptr);
    const int rows = TriangleMeshes::subdivisions(3, 32);
    EXPECT_EQ(first.mesh->triangles.size(), static_cast<std::size_t>(rows * rows));
    meshes.update(d, 32);
    EXPECT_EQ(meshes.view(1).revision, first.revision);
    d.objects[0].triangle()->weights[0] = 3;
    meshes.update(d, 32);
    EXPECT_NE(meshes.view(1).revision, first.revision);
    d.objects[0].visible = false;
    meshes.update(d, 32);
    EXPECT_EQ(meshes.view(1).mesh, nullptr);
}

TEST(TriangleScene, BuildSceneDrawsTheMeshTheSelectedPointAndTheIndicator) {
    const doc::Document d = triangle_document();
    TriangleMeshes meshes;
    meshes.update(d, d.view.display.density);
    const BuiltScene scene = build_scene(d, {}, nullptr, &meshes);
    ASSERT_EQ(scene.surfaces.size(), 1u);
    EXPECT_EQ(scene.surfaces[0].mesh, meshes.view(1).mesh);
    const glm::vec3 selected(d.objects[0].triangle()->points[geom::TrianglePatch::index(3, 1, 1)]);
    const glm::vec3 indicator(
        geom::triangle_point(*d.objects[0].triangle(), d.view.barycentric).value());
    bool saw_selected = false, saw_indicator = false;
    for (const PointBatch& b : scene.overlay.points)
        for (const OverlayVertex& v : b.points) {
            saw_selected |= glm::length(v.position - selected) < 1e-6f && b.size_px >= 13;
            saw_indicator |= glm::length(v.position - indicator) < 1e-6f && b.sphere;
        }
    EXPECT_TRUE(saw_selected);
    EXPECT_TRUE(saw_indicator);
}
