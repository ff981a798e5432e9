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

// The closed form n! / (i! j! k!) r^i s^j t^k, with pow's 0^0 = 1.
double closed_form(int n, int i, int j, const Barycentric& p) {
    const int k = n - i - j;
    return factorial(n) / (factorial(i) * factorial(j) * factorial(k)) * std::pow(p[0], i) *
           std::pow(p[1], j) * std::pow(p[2], k);
}

TEST(TriangleBernstein, SumsToOneAndMatchesTheClosedForm) {
    for (int n : {1, 2, 3, 5, 10, 40}) { // 40: above exact_bernstein_degree, in logarithms
        for (const Barycentric& p : samples) {
            double sum = 0;
            for (int i = n; i >= 0; --i)
                for (int j = n - i; j >= 0; --j) {
                    const double B = bernstein_triangle(n, i, j, p);
                    EXPECT_NEAR(B, closed_form(n, i, j, p), 1e-13)
                        << "n " << n << " b_" << i << j << n - i - j;
                    EXPECT_GE(B, 0.0);
                    sum += B;
                }
            EXPECT_NEAR(sum, 1.0, 1e-13) << "n " << n;
        }
    }
    // At a vertex only that vertex's function is non-zero, and exactly 1 (interpolation).
    EXPECT_EQ(bernstein_triangle(4, 4, 0, {1, 0, 0}), 1.0);
    EXPECT_EQ(bernstein_triangle(4, 3, 1, {1, 0, 0}), 0.0);
    EXPECT_EQ(bernstein_triangle(4, 0, 0, {0, 0, 1}), 1.0);
}

TEST(TriangleBernstein, OutsideTheTriangleKeepsThePolynomialsSign) {
    // (r, s, t) = (1.3, -0.2, -0.1): s^1 is negative, t^2 positive.
    const Barycentric p = {1.3, -0.2, -0.1};
    EXPECT_NEAR(bernstein_triangle(4, 1, 1, p), closed_form(4, 1, 1, p), 1e-13);
    EXPECT_LT(bernstein_triangle(4, 1, 1, p), 0.0);
    EXPECT_NEAR(bernstein_triangle(4, 1, 2, p), closed_form(4, 1, 2, p), 1e-13);
    double sum = 0;
    for (int i = 4; i >= 0; --i)
        for (int j = 4 - i; j >= 0; --j) sum += bernstein_triangle(4, i, j, p);
    EXPECT_NEAR(sum, 1.0, 1e-12); // (r + s + t)^n = 1 anywhere on the plane
}

TEST(TriangleBernstein, HighDegreesStayFiniteWhereTheCoefficientOverflows) {
    // 300! / (100!)^3 is about 1e141 times 3^-300 about 1e-143: neither fits alone in a
    // double's exponent range, the product (about 1e-3) does.
    const int n = 300;
    const Barycentric centre = {1.0 / 3, 1.0 / 3, 1.0 / 3};
    const double B = bernstein_triangle(n, 100, 100, centre);
    EXPECT_TRUE(std::isfinite(B));
    EXPECT_GT(B, 1e-4);
    double sum = 0;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) sum += bernstein_triangle(n, i, j, {0.2, 0.3, 0.5});
    EXPECT_NEAR(sum, 1.0, 1e-9);
}

TEST(TriangleBernstein, EachFunctionPeaksAtItsDomainPoint) {
    // B^n_ijk is largest at (i, j, k) / n (its gradient on the plane vanishes there).
    const int n = 4, grid = 48;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) {
            const double peak =
                bernstein_triangle(n, i, j,
                                   {static_cast<double>(i) / n, static_cast<double>(j) / n,
                                    static_cast<double>(n - i - j) / n});
            for (int a = 0; a <= grid; ++a)
                for (int b = 0; a + b <= grid; ++b) {
                    const Barycentric p = {static_cast<double>(a) / grid,
                                           static_cast<double>(b) / grid,
                                           static_cast<double>(grid - a - b) / grid};
                    EXPECT_LE(bernstein_triangle(n, i, j, p), peak + 1e-15);
                }
        }
}

TEST(TriangleBernstein, RationalBasisSumsToOneAndRebuildsThePatch) {
    const TrianglePatch T = random_triangle(3, true, 5);
    for (const Barycentric& p : samples) {
        glm::dvec3 point(0.0);
        double sum = 0;
        for (int i = 3; i >= 0; --i)
            for (int j = 3 - i; j >= 0; --j) {
                const auto R = rational_bernstein_triangle(T, i, j, p);
                ASSERT_TRUE(R);
                sum += *R;
                point += *R * T.points[TrianglePatch::index(3, i, j)];
            }
        EXPECT_NEAR(sum, 1.0, 1e-13);
        // sum R_ijk b_ijk is the patch point de Casteljau computes.
        EXPECT_LT(glm::length(point - *triangle_point(T, p)), 1e-13);
    }
    // Unit weights: R is B.
    const TrianglePatch U = random_triangle(3, false, 6);
    EXPECT_NEAR(*rational_bernstein_triangle(U, 1, 1, {0.2, 0.3, 0.5}),
                bernstein_triangle(3, 1, 1, {0.2, 0.3, 0.5}), 1e-15);
    // Weights 1, -1, 7 of a linear patch: sum w B = 0 at the midpoint of the edge t = 0, where
    // the patch goes to infinity and R does not exist; elsewhere it does.
    TrianglePatch L = random_triangle(1, true, 7);
    L.weights = {1, -1, 7};
    EXPECT_FALSE(rational_bernstein_triangle(L, 1, 0, {0.5, 0.5, 0}));
    EXPECT_TRUE(rational_bernstein_triangle(L, 1, 0, {0.4, 0.4, 0.2}));
}

} // namespace
