// The interactive tessellator: threads give bit-identical meshes; a local update after moving
// one control point equals a full re-tessellation; gaps where points do not exist.
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "core/geom/grid_tessellator.hpp"
#include "core/geom/knots.hpp"
#include "tests/support/random_geometry.hpp"
#include "tests/support/small_surfaces.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

TEST(GridTessellator, ThreadsAreBitIdentical) {
    RandomGeometry g(61);
    const Surface s = g.surface(3, 3, 12, 9, true);
    const GridTessellator t(s, 65, 47);
    Mesh one, two;
    t.evaluate(s, one, 1);
    t.evaluate(s, two, 2);
    EXPECT_EQ(one.positions, two.positions);
    EXPECT_EQ(one.normals, two.normals);
    EXPECT_EQ(one.triangles, two.triangles);
}

// With what the tasks do beyond the kernel too: degenerate normals, settled in the tasks (a
// pole: control row 0 collapsed to one point), and points that do not exist, settled after
// them (w = 1 - 2u: the row u = 1/2). Grids of many column blocks, two and three threads.
TEST(GridTessellator, ThreadsAreBitIdenticalWithPolesAndGaps) {
    RandomGeometry g(66);
    Surface pole = g.surface(3, 3, 9, 12, true);
    for (int j = 0; j < pole.n_v; ++j) pole.point(0, j) = pole.point(0, 0);
    Surface gaps = isoparm::testing::bilinear_patch(1, 1, -1, -1);
    for (const Surface* s : {&pole, &gaps}) {
        const GridTessellator t(*s, 129, 203);
        Mesh one;
        t.evaluate(*s, one, 1);
        EXPECT_EQ(one.exists.empty(), s == &pole);
        for (int j = 0; s == &pole && j < t.samples_v(); ++j)
            EXPECT_NEAR(glm::length(one.normals[j]), 1.0, 1e-12) << j; // the limit, not 0 / 0
        for (int threads : {2, 3}) {
            Mesh many;
            t.evaluate(*s, many, threads);
            EXPECT_EQ(one.positions, many.positions);
            EXPECT_EQ(one.normals, many.normals);
            EXPECT_EQ(one.exists, many.exists);
            EXPECT_EQ(one.triangles, many.triangles);
        }
    }
}

TEST(GridTessellator, LocalUpdateEqualsFullPass) {
    RandomGeometry g(62);
    for (int trial = 0; trial < 10; ++trial) {
        Surface s = g.surface(g.integer(1, 4), g.integer(1, 4), 10, 8, trial % 2 == 0);
        const GridTessellator t(s, 41, 33);
        Mesh mesh;
        t.evaluate(s, mesh);
        const int i = g.integer(0, s.n_u - 1), j = g.integer(0, s.n_v - 1);
        s.point(i, j) += glm::dvec3(0.3, -0.2, 0.7);
        if (trial % 2 == 0) s.weight(i, j) *= 1.7;
        t.update_control_point(s, mesh, i, j);
        Mesh full;
        t.evaluate(s, full);
        EXPECT_EQ(mesh.positions, full.positions);
        EXPECT_EQ(mesh.normals, full.normals);
        const auto [r0, r1] = t.rows_touching(i);
        EXPECT_LE(r0, r1);
        EXPECT_LT(r1 - r0 + 1, t.samples_u()); // local: not every row (10 points, degree <= 4)
    }
}

TEST(GridTessellator, FitsOnlyTheSameLayout) {
    RandomGeometry g(63);
    Surface s = g.surface(2, 3, 6, 7, true);
    const GridTessellator t(s, 10, 10);
    EXPECT_TRUE(t.fits(s, 10, 10));
    s.points[3] += glm::dvec3(1.0);
    EXPECT_TRUE(t.fits(s, 10, 10)); // control points do not change the tables
    EXPECT_FALSE(t.fits(s, 11, 10));
    s.knots_u[3] += 1e-9;
    EXPECT_FALSE(t.fits(s, 10, 10));
}

TEST(GridTessellator, PointsThatDoNotExistLeaveGaps) {
    // Weights (1, -1) in u: the denominator vanishes along u = 0.5.
    Surface s = isoparm::testing::bilinear_patch(1, 1, -1, -1);
    const GridTessellator t(s, 3, 3);
    Mesh m;
    t.evaluate(s, m);
    ASSERT_FALSE(m.exists.empty());
    EXPECT_FALSE(m.vertex_exists(3)); // (u, v) = (0.5, 0)
    EXPECT_TRUE(m.vertex_exists(0));
    for (const auto& tri : m.triangles)
        for (auto k : tri) EXPECT_TRUE(m.vertex_exists(k));
    // Making the weight positive again closes the gap through a local update.
    s.weight(1, 0) = s.weight(1, 1) = 1;
    t.update_control_point(s, m, 1, 0);
    t.update_control_point(s, m, 1, 1);
    EXPECT_TRUE(m.exists.empty());
    EXPECT_EQ(m.triangles.size(), 8u);
}

TEST(GridTessellator, PositionsOnlyEqualTheFullPass) {
    RandomGeometry g(64);
    const Surface s = g.surface(3, 2, 9, 7, true);
    const GridTessellator t(s, 33, 21);
    Mesh full;
    t.evaluate(s, full);
    std::vector<glm::dvec3> positions;
    std::vector<std::uint8_t> exists;
    t.evaluate_positions(s, positions, exists, 2);
    EXPECT_EQ(positions, full.positions);
    EXPECT_TRUE(exists.empty());
}
