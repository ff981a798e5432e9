// Blossoms: symmetric, multi-affine, the diagonal is the curve, control points are blossom
// values at consecutive knots (rational too), and knot insertion is one new blossom argument.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>

#include "core/geom/blossom.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

double gap(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(a - b) / std::max(1.0, glm::length(b));
}

Curve random_curve(RandomGeometry& g, int p, int n, bool rational) {
    Curve c = g.curve(p, n, rational);
    c.knots = clamped_uniform_knots(n, p);
    if (rational)
        for (double& w : c.weights) w = g.uniform(0.5, 2.0);
    return c;
}

class Blossom : public ::testing::TestWithParam<bool> {}; // rational or not

TEST_P(Blossom, IsSymmetricAndMultiAffine) {
    RandomGeometry g(11);
    for (int p = 1; p <= 5; ++p) {
        const Curve c = random_curve(g, p, p + 4, GetParam());
        const int J = p + 2;
        std::vector<double> a(p);
        for (double& x : a) x = g.uniform(-0.5, 1.5);
        const glm::dvec3 f = *curve_blossom(c, J, a);
        // Symmetric: any order of the arguments.
        std::vector<double> b = a;
        std::reverse(b.begin(), b.end());
        EXPECT_LT(gap(*curve_blossom(c, J, b), f), 1e-12) << p;
        if (GetParam()) continue; // a rational blossom is multi-affine in homogeneous space only
        // Affine in the first argument: f(l x + (1 - l) y, ...) = l f(x, ...) + (1 - l) f(y, ...).
        std::vector<double> x = a, y = a, mix = a;
        x[0] = 0.1, y[0] = 0.8;
        const double l = 0.3;
        mix[0] = l * x[0] + (1 - l) * y[0];
        const glm::dvec3 expected = l * *curve_blossom(c, J, x) + (1 - l) * *curve_blossom(c, J, y);
        EXPECT_LT(gap(*curve_blossom(c, J, mix), expected), 1e-12) << p;
    }
}

TEST_P(Blossom, DiagonalIsTheCurveAndConsecutiveKnotsAreControlPoints) {
    RandomGeometry g(12);
    for (int p = 1; p <= 5; ++p) {
        const Curve c = random_curve(g, p, p + 5, GetParam());
        for (int J = p; J < c.count(); ++J) {
            if (!(c.knots[J] < c.knots[J + 1])) continue;
            const double t = 0.5 * (c.knots[J] + c.knots[J + 1]);
            EXPECT_LT(gap(*curve_blossom(c, J, std::vector<double>(p, t)), *curve_point(c, t)),
                      1e-13);
            for (int i = J - p; i <= J; ++i) {
                const std::vector<double> knots(c.knots.begin() + i + 1,
                                                c.knots.begin() + i + p + 1);
                EXPECT_LT(gap(*curve_blossom(c, J, knots), c.points[i]), 1e-13) << p << " " << i;
            }
        }
    }
}

// Boehm's insertion of t into [U[J], U[J+1]): the new control points are the blossom values of
// the piece at consecutive knots of the refined vector (one new argument each).
TEST_P(Blossom, KnotInsertionEvaluatesTheBlossomWithOneNewArgument) {
    RandomGeometry g(13);
    const int p = 3;
    const Curve c = random_curve(g, p, 8, GetParam());
    const double t = 0.43;
    const int J = find_span(c.knots, p, c.count(), t);
    auto refined = insert_knot(c, t, 1);
    ASSERT_TRUE(refined.ok());
    for (int i = J - p + 1; i <= J; ++i) { // the points the insertion replaced
        const std::vector<double> args(refined->knots.begin() + i + 1,
                                       refined->knots.begin() + i + p + 1);
        EXPECT_LT(gap(*curve_blossom(c, J, args), refined->points[i]), 1e-13) << i;
    }
}

TEST_P(Blossom, SurfaceBlossomReproducesPointsAndControlPoints) {
    RandomGeometry g(14);
    Surface s = g.surface(3, 2, 6, 5, GetParam());
    s.knots_u = clamped_uniform_knots(6, 3);
    s.knots_v = clamped_uniform_knots(5, 2);
    if (GetParam())
        for (double& w : s.weights) w = g.uniform(0.5, 2.0);
    const double u = 0.61, v = 0.27;
    const int Ju = find_span(s.knots_u, 3, 6, u), Jv = find_span(s.knots_v, 2, 5, v);
    EXPECT_LT(gap(*surface_blossom(s, Ju, Jv, {u, u, u}, {v, v}), *surface_point(s, u, v)), 1e-13);
    for (int i = Ju - 3; i <= Ju; ++i) {
        for (int j = Jv - 2; j <= Jv; ++j) {
            const std::vector<double> ua(s.knots_u.begin() + i + 1, s.knots_u.begin() + i + 4);
            const std::vector<double> va(s.knots_v.begin() + j + 1, s.knots_v.begin() + j + 3);
            EXPECT_LT(gap(*surface_blossom(s, Ju, Jv, ua, va), s.point(i, j)), 1e-13);
        }
    }
}

TEST_P(Blossom, EveryDeBoorPointIsTheBlossomAtItsLabelledArguments) {
    RandomGeometry g(29);
    for (int p = 1; p <= 5; ++p) {
        const Curve c = random_curve(g, p, p + 5, GetParam());
        const Interval dom = domain(c);
        const double t = g.uniform(dom.lo, dom.hi);
        const DeBoorTriangle tri = deboor_curve(c, t);
        for (int k = 0; k <= p; ++k)
            for (std::size_t i = 0; i < tri.levels[k].size(); ++i) {
                const int index = tri.first_index + static_cast<int>(i) + k;
                const std::vector<double> args = deboor_point_arguments(c.knots, p, k, index, t);
                ASSERT_EQ(args.size(), static_cast<std::size_t>(p));
                for (int a = 0; a < k; ++a) EXPECT_EQ(args[a], t);
                const glm::dvec3 f = *curve_blossom(c, tri.span, args);
                EXPECT_LT(gap(f, *DeBoorTriangle::cartesian(tri.levels[k][i])), 1e-12)
                    << "p " << p << " level " << k << " index " << index;
            }
    }
}

INSTANTIATE_TEST_SUITE_P(PolynomialAndRational, Blossom, ::testing::Bool());

TEST(BlossomSpan, DefaultsToThePieceOfTheFirstArgumentAndChecksExplicitOnes) {
    const Knots U = {0, 0, 0, 0.5, 0.5, 1, 1, 1}; // p = 2, n = 5: pieces 2 ([0, .5)) and 4
    EXPECT_EQ(default_blossom_span(U, 2, 5, 0.25), 2);
    EXPECT_EQ(default_blossom_span(U, 2, 5, 0.5), 4); // right limit at the double knot
    EXPECT_EQ(default_blossom_span(U, 2, 5, 1.0), 4); // the end takes the left limit
    EXPECT_EQ(default_blossom_span(U, 2, 5, -3.0), 2);
    EXPECT_EQ(default_blossom_span(U, 2, 5, 7.0), 4);
    EXPECT_TRUE(check_blossom_span(U, 2, 5, 4, "/span").ok());
    EXPECT_EQ(check_blossom_span(U, 2, 5, 3, "/span").error().path, "/span"); // empty
    EXPECT_FALSE(check_blossom_span(U, 2, 5, 1, "/span").ok());
    EXPECT_FALSE(check_blossom_span(U, 2, 5, 5, "/span").ok());
}

} // namespace
