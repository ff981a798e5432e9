// The renderer's incremental mesh: local updates give the same mesh as a full tessellation.
#include <gtest/gtest.h>

#include <cmath>

#include "core/doc/document.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/incremental_mesh.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

geom::Surface shaped(int n) {
    geom::Surface s = doc::make_planar_grid(n, n, 3, 3, geom::SplineType::nurbs);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            s.point(i, j).z = std::sin(0.5 * i) * std::cos(0.4 * j);
            s.weight(i, j) = 1.0 + 0.25 * std::sin(0.3 * i + 0.2 * j);
        }
    return s;
}

void expect_same_mesh(const geom::Mesh& a, const geom::Mesh& b) {
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (std::size_t k = 0; k < a.positions.size(); ++k) {
        EXPECT_NEAR(a.positions[k].x, b.positions[k].x, 1e-12);
        EXPECT_NEAR(a.positions[k].y, b.positions[k].y, 1e-12);
        EXPECT_NEAR(a.positions[k].z, b.positions[k].z, 1e-12);
    }
    EXPECT_EQ(a.triangles, b.triangles);
}

} // namespace

TEST(IncrementalMesh, FirstUpdateIsFullSecondIsNothing) {
    const geom::Surface s = shaped(8);
    IncrementalMesh m;
    const MeshChange first = m.update(s, 40, 40);
    EXPECT_TRUE(first.any);
    EXPECT_TRUE(first.topology);
    EXPECT_EQ(first.vertex_count, 1600);
    EXPECT_FALSE(m.update(s, 40, 40).any);
}

TEST(IncrementalMesh, MovingOnePointUpdatesOnlyItsRowsAndMatchesAFullTessellation) {
    geom::Surface s = shaped(12);
    IncrementalMesh m;
    m.update(s, 60, 60);
    s.point(5, 7).z += 0.8;
    const MeshChange c = m.update(s, 60, 60);
    EXPECT_TRUE(c.any);
    EXPECT_FALSE(c.topology);
    EXPECT_GT(c.vertex_count, 0);
    EXPECT_LT(c.vertex_count, 60 * 60 / 2); // local support: far fewer than all rows
    EXPECT_EQ(c.first_vertex % 60, 0);
    expect_same_mesh(m.mesh(), geom::tessellate(s, 60, 60));
}

TEST(IncrementalMesh, WeightChangesAndManyMovesStayCorrect) {
    geom::Surface s = shaped(10);
    IncrementalMesh m;
    m.update(s, 33, 33);
    s.weight(2, 3) = 4.0;
    EXPECT_TRUE(m.update(s, 33, 33).any);
    expect_same_mesh(m.mesh(), geom::tessellate(s, 33, 33));
    for (glm::dvec3& p : s.points) p.x += 1; // a translation moves all: full rebuild
    const MeshChange c = m.update(s, 33, 33);
    EXPECT_EQ(c.vertex_count, 33 * 33);
    expect_same_mesh(m.mesh(), geom::tessellate(s, 33, 33));
}

TEST(IncrementalMesh, LayoutOrSamplingChangesRebuild) {
    geom::Surface s = shaped(6);
    IncrementalMesh m;
    m.update(s, 20, 20);
    EXPECT_EQ(m.update(s, 25, 20).vertex_count, 500);
    s.knots_u[4] = 0.3; // interior knot moved
    EXPECT_TRUE(m.update(s, 25, 20).topology);
    expect_same_mesh(m.mesh(), geom::tessellate(s, 25, 20));
}

TEST(IncrementalMesh, ZeroWeightHolesChangeTheTopology) {
    // A Bezier patch with a zero-weight corner: the corner point of the surface vanishes.
    geom::Surface s = doc::make_planar_grid(2, 2, 1, 1, geom::SplineType::rational_bezier);
    IncrementalMesh m;
    m.update(s, 5, 5);
    s.weight(0, 0) = 0;
    const MeshChange c = m.update(s, 5, 5);
    EXPECT_TRUE(c.topology);
    expect_same_mesh(m.mesh(), geom::tessellate(s, 5, 5));
}
