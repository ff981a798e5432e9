// Triangular Bezier patches: de Casteljau equals the Bernstein sum, elevation and split keep
// the shape, derivatives match differences, rational patches too.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/triangle.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;

namespace {

TrianglePatch random_triangle(int n, bool rational, unsigned seed) {
    isoparm::testing::RandomGeometry g(seed);
    TrianglePatch t;
    t.rational = rational;
    t.degree = n;
    for (int k = 0; k < TrianglePatch::count_for(n); ++k) {
        t.points.push_back({g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)});
        t.weights.push_back(rational ? g.uniform(0.5, 2) : 1.0);
    }
    return t;
}

double factorial(int n) {
    return n <= 1 ? 1.0 : n * factorial(n - 1);
}

// sum B^n_ijk(r, s, t) w_ijk b_ijk / sum B^n_ijk w_ijk, term by term.
glm::dvec3 bernstein_sum(const TrianglePatch& T, const Barycentric& p) {
    const int n = T.degree;
    glm::dvec3 num(0.0);
    double den = 0;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) {
            const int k = n - i - j;
            const double B = factorial(n) / (factorial(i) * factorial(j) * factorial(k)) *
                             std::pow(p[0], i) * std::pow(p[1], j) * std::pow(p[2], k);
            const int at = TrianglePatch::index(n, i, j);
            num += B * T.weights[at] * T.points[at];
            den += B * T.weights[at];
        }
    return num / den;
}

const Barycentric samples[] = {{1, 0, 0},
                               {0, 1, 0},
                               {0, 0, 1},
                               {0.2, 0.3, 0.5},
                               {0.6, 0.1, 0.3},
                               {0.5, 0.5, 0},
                               {1.0 / 3, 1.0 / 3, 1.0 / 3}};

TEST(Triangle, OrderPutsBn00FirstAndB00nLast) {
    EXPECT_EQ(TrianglePatch::index(3, 3, 0), 0);
    EXPECT_EQ(TrianglePatch::index(3, 2, 1), 1);
    EXPECT_EQ(TrianglePatch::index(3, 2, 0), 2);
    EXPECT_EQ(TrianglePatch::index(3, 0, 0), 9);
}

TEST(Triangle, DeCasteljauIsTheBernsteinSumAndItsLastLevel) {
    for (bool rational : {false, true}) {
        for (int n = 1; n <= 6; ++n) {
            const TrianglePatch T = random_triangle(n, rational, 100 + n);
            for (const Barycentric& p : samples) {
                const glm::dvec3 expected = bernstein_sum(T, p);
                EXPECT_LT(glm::length(*triangle_point(T, p) - expected), 1e-13);
                const auto levels = triangle_de_casteljau(T, p);
                ASSERT_EQ(static_cast<int>(levels.size()), n + 1);
                ASSERT_EQ(levels.back().size(), 1u);
                EXPECT_LT(glm::length(*levels.back()[0] - expected), 1e-13);
                EXPECT_EQ(*levels[0][3 % levels[0].size()], T.points[3 % T.points.size()]);
            }
            // The corners are the corner control points (rational: (w b) / w, to the last bit
            // or one rounding away).
            EXPECT_LT(glm::length(*triangle_point(T, {1, 0, 0}) - T.points.front()), 1e-15);
            EXPECT_LT(glm::length(*triangle_point(T, {0, 0, 1}) - T.points.back()), 1e-15);
        }
    }
}

TEST(Triangle, ElevationKeepsTheShape) {
    for (bool rational : {false, true}) {
        const TrianglePatch T = random_triangle(3, rational, 7);
        const TrianglePatch E = elevate_triangle(T, 2);
        EXPECT_EQ(E.degree, 5);
        ASSERT_EQ(static_cast<int>(E.points.size()), TrianglePatch::count_for(5));
        for (const Barycentric& p : samples)
            EXPECT_LT(glm::length(*triangle_point(E, p) - *triangle_point(T, p)), 1e-13);
    }
}

// Piece v covers the sub-triangle with the split point in place of vertex v: a point with
// barycentric coordinates q in piece 0 is q0 P + q1 V1 + q2 V2 in the original's coordinates.
TEST(Triangle, SplitPiecesCoverThePatchExactly) {
    for (bool rational : {false, true}) {
        const TrianglePatch T = random_triangle(4, rational, 9);
        const Barycentric P = {0.2, 0.5, 0.3};
        auto pieces = split_triangle(T, P);
        ASSERT_TRUE(pieces.ok());
        for (int v = 0; v < 3; ++v) {
            for (const Barycentric& q : samples) {
                Barycentric original{};
                for (int c = 0; c < 3; ++c) {
                    const double vertex = c == v ? 0.0 : 1.0; // the kept vertices
                    original[c] = q[v] * P[c] + (c == v ? 0.0 : q[c] * vertex);
                }
                EXPECT_LT(
                    glm::length(*triangle_point((*pieces)[v], q) - *triangle_point(T, original)),
                    1e-13)
                    << v;
            }
        }
        EXPECT_LT(glm::length((*pieces)[0].points.front() - *triangle_point(T, P)), 1e-14);
    }
}

TEST(Triangle, DerivativesMatchCentralDifferences) {
    for (bool rational : {false, true}) {
        const TrianglePatch T = random_triangle(4, rational, 11);
        const Barycentric p = {0.3, 0.4, 0.3};
        const auto D = triangle_derivatives(T, p, 2);
        ASSERT_TRUE(D);
        const double h = 1e-5;
        auto at = [&](double dr, double ds) {
            return *triangle_point(T, {p[0] + dr, p[1] + ds, p[2] - dr - ds});
        };
        const glm::dvec3 Sr = (at(h, 0) - at(-h, 0)) / (2 * h),
                         Ss = (at(0, h) - at(0, -h)) / (2 * h);
        const glm::dvec3 Srr = (at(h, 0) - 2.0 * at(0, 0) + at(-h, 0)) / (h * h);
        const glm::dvec3 Srs = (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4 * h * h);
        EXPECT_LT(glm::length((*D)[1][0] - Sr), 1e-7);
        EXPECT_LT(glm::length((*D)[0][1] - Ss), 1e-7);
        EXPECT_LT(glm::length((*D)[2][0] - Srr), 1e-3);
        EXPECT_LT(glm::length((*D)[1][1] - Srs), 1e-3);
        EXPECT_EQ((*D)[0][0], *triangle_point(T, p));
    }
}

} // namespace
