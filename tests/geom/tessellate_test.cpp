// Tessellation: vertices agree with evaluation, normals with the strict or limit normal.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

TEST(Tessellate, VerticesAndNormalsMatchEvaluation) {
    RandomGeometry g(51);
    for (int trial = 0; trial < 12; ++trial) {
        const Surface s =
            g.surface(g.integer(1, 4), g.integer(1, 4), 7, 6, trial % 2 == 0, trial % 3 != 0);
        const int nu = g.integer(2, 17), nv = g.integer(2, 17);
        const Mesh m = tessellate(s, nu, nv);
        ASSERT_EQ(m.positions.size(), static_cast<size_t>(nu * nv));
        ASSERT_EQ(m.triangles.size(), static_cast<size_t>(2 * (nu - 1) * (nv - 1)));
        const auto us = uniform_params(s.knots_u[s.degree_u], s.knots_u[s.n_u], nu);
        const auto vs = uniform_params(s.knots_v[s.degree_v], s.knots_v[s.n_v], nv);
        for (int i = 0; i < nu; ++i) {
            for (int j = 0; j < nv; ++j) {
                const size_t k = static_cast<size_t>(i) * nv + j;
                EXPECT_LT(glm::length(m.positions[k] - *surface_point(s, us[i], vs[j])), 1e-11);
                EXPECT_LT(glm::length(m.normals[k] - surface_normal_or_limit(s, us[i], vs[j])),
                          1e-9);
            }
        }
    }
}

TEST(Tessellate, TrianglesAreCounterClockwiseAboutTheNormal) {
    // A gentle height field over the xy-plane (random nets fold over themselves).
    RandomGeometry g(52);
    Surface s = g.surface(3, 2, 6, 5, true);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) s.point(i, j) = {i, j, g.uniform(-0.3, 0.3)};
    const Mesh m = tessellate(s, 9, 7);
    for (const auto& t : m.triangles) {
        const glm::dvec3 f = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                                        m.positions[t[2]] - m.positions[t[0]]);
        EXPECT_GT(glm::dot(f, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]), 0.0);
    }
}

TEST(Tessellate, UniformParamsAreExactAtEnds) {
    const auto t = uniform_params(-2.348, 1.173, 7);
    EXPECT_EQ(t.front(), -2.348);
    EXPECT_EQ(t.back(), 1.173);
}

TEST(Tessellate, TriangleLayoutIsUMajor) {
    RandomGeometry g(3);
    const Mesh m = tessellate(g.surface(2, 2, 3, 3, false), 4, 6);
    ASSERT_GE(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[0], (std::array<std::uint32_t, 3>{0, 6, 7}));
    EXPECT_EQ(m.triangles[1], (std::array<std::uint32_t, 3>{0, 7, 1}));
}

TEST(Tessellate, PoleNormalIsTheLimitFromInside) {
    // Shared example 0066: a sphere octant whose row u = 0 collapses to the pole (0, 0, 1);
    // rounding leaves S_v ~ 1e-17 there, not 0, which must still count as degenerate.
    Surface s;
    s.type = SplineType::nurbs;
    s.degree_u = s.degree_v = 2;
    s.n_u = s.n_v = 3;
    s.knots_u = s.knots_v = bezier_knots(2);
    s.points = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1},
                {0, 1, 1}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const double r = 0.7071067811865476;
    s.weights = {1, r, 1, r, 0.5000000000000001, r, 1, r, 1};
    const Mesh m = tessellate(s, 5, 4);
    for (int j = 0; j < 4; ++j) {
        EXPECT_NEAR(m.normals[j].x, 0.0, 1e-9);
        EXPECT_NEAR(m.normals[j].y, 0.0, 1e-9);
        EXPECT_NEAR(m.normals[j].z, 1.0, 1e-9);
    }
    EXPECT_FALSE(surface_normal(s, 0.0, 2.0 / 3).has_value()); // strictly: no normal at a pole
}
