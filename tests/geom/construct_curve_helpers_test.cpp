// Curve designer helpers: banded LU, parametrizations, averaged knots, interpolation, primitives.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/banded_lu.hpp"
#include "core/geom/interpolate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/validate.hpp"
#include "tests/geom/construct_test_util.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;
using isoparm::testing::samples;

TEST(BandedLU, SolvesBandedSystemsThatNeedPivoting) {
    RandomGeometry g(651);
    for (int trial = 0; trial < 50; ++trial) {
        const int n = g.integer(1, 30), kl = g.integer(0, 3), ku = g.integer(0, 3);
        std::vector<std::vector<double>> A(n, std::vector<double>(n, 0.0));
        BandedLU lu(n, kl, ku);
        for (int i = 0; i < n; ++i)
            for (int j = std::max(0, i - kl); j <= std::min(n - 1, i + ku); ++j) {
                // Zero diagonals in half the trials: only pivoting gets through them.
                A[i][j] = (i == j && trial % 2 == 0 && kl > 0) ? 0.0 : g.uniform(-1, 1);
                lu.set(i, j, A[i][j]);
            }
        std::vector<double> x(n), b(n, 0.0);
        for (int i = 0; i < n; ++i) x[i] = g.uniform(-3, 3);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) b[i] += A[i][j] * x[j];
        if (!lu.factor()) continue; // a random singular matrix: nothing to check
        lu.solve(b.data());
        for (int i = 0; i < n; ++i) EXPECT_NEAR(b[i], x[i], 1e-6) << "trial " << trial;
    }
}

TEST(BandedLU, ReportsSingularMatrices) {
    BandedLU lu(3, 1, 1);
    lu.set(0, 0, 1);
    lu.set(0, 1, 2);
    lu.set(1, 0, 2);
    lu.set(1, 1, 4);
    lu.set(2, 2, 1);
    EXPECT_FALSE(lu.factor());
}

TEST(Interpolate, PassesThroughEveryPointAtItsParameter) {
    RandomGeometry g(652);
    for (Parametrization mode :
         {Parametrization::chord, Parametrization::centripetal, Parametrization::uniform}) {
        for (int trial = 0; trial < 30; ++trial) {
            const int n = g.integer(2, 20);
            std::vector<glm::dvec3> pts;
            for (int k = 0; k < n; ++k)
                pts.push_back({g.uniform(-5, 5), g.uniform(-5, 5), g.uniform(-5, 5)});
            const int p = g.integer(1, std::min(5, n - 1));
            auto r = interpolate_curve(pts, p, mode);
            ASSERT_TRUE(r.ok()) << r.error().message;
            ASSERT_TRUE(validate_curve(r->curve).ok());
            EXPECT_EQ(r->curve.knots, averaged_knots(r->params, p));
            for (int k = 0; k < n; ++k)
                EXPECT_LT(glm::distance(*curve_point(r->curve, r->params[k]), pts[k]), 1e-9);
        }
    }
}

TEST(Interpolate, ParametersAndAveragedKnots) {
    const std::vector<glm::dvec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 4, 0}, {1, 4, 4}, {1, 4, 8}};
    auto chord = point_params(pts, Parametrization::chord);
    ASSERT_TRUE(chord.ok());
    const std::vector<double> want = {0, 1.0 / 13, 5.0 / 13, 9.0 / 13, 1};
    for (int k = 0; k < 5; ++k) EXPECT_DOUBLE_EQ((*chord)[k], want[k]);
    auto centripetal = point_params(pts, Parametrization::centripetal);
    ASSERT_TRUE(centripetal.ok());
    EXPECT_DOUBLE_EQ((*centripetal)[1], 1.0 / 7);
    EXPECT_DOUBLE_EQ((*centripetal)[2], 3.0 / 7);
    auto uniform = point_params(pts, Parametrization::uniform);
    EXPECT_EQ(*uniform, (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
    // Eq. 9.8 with p = 2 and five points: interior knots (t1 + t2) / 2 and (t2 + t3) / 2.
    const Knots U = averaged_knots(*chord, 2);
    EXPECT_EQ(U.size(), 8u);
    EXPECT_DOUBLE_EQ(U[3], (1.0 / 13 + 5.0 / 13) / 2);
    EXPECT_DOUBLE_EQ(U[4], (5.0 / 13 + 9.0 / 13) / 2);
    auto k = knots_for_points(pts, 2, KnotMode::chord);
    ASSERT_TRUE(k.ok());
    EXPECT_EQ(*k, U);
    EXPECT_EQ(*knots_for_points(pts, 3, KnotMode::clamped_uniform), clamped_uniform_knots(5, 3));
    auto kc = knots_for_points(pts, 1, KnotMode::centripetal);
    EXPECT_EQ(*kc, averaged_knots(*centripetal, 1));
}

TEST(Interpolate, DegenerateInputIsAnError) {
    const std::vector<glm::dvec3> same = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
    auto r = interpolate_curve(same, 2, Parametrization::chord);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::geometry);
    EXPECT_EQ(r.error().path, "/points");
    const std::vector<glm::dvec3> repeated = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    r = interpolate_curve(repeated, 2, Parametrization::centripetal);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/points/2");
    r = interpolate_curve(repeated, 4, Parametrization::uniform);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::degree);
    EXPECT_EQ(r.error().path, "/degree");
    r = interpolate_curve({{0, 0, 0}}, 1, Parametrization::uniform);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
}

TEST(Primitives, ArcsAreExactAndSpanTheirAngles) {
    const glm::dvec3 centre{1, -2, 0.5};
    for (Plane plane : {Plane::xy, Plane::xz, Plane::yz}) {
        glm::dvec3 X, Y;
        plane_axes(plane, X, Y);
        for (auto [a0, a1] :
             {std::pair{0.0, 45.0}, {10.0, 100.0}, {-30.0, 150.0}, {20.0, 290.0}, {5.0, 365.0}}) {
            auto c = circular_arc(centre, 1.5, a0, a1, plane);
            ASSERT_TRUE(c.ok()) << c.error().message;
            ASSERT_TRUE(validate_curve(*c).ok());
            EXPECT_EQ(c->degree, 2);
            const int arcs = (c->count() - 1) / 2;
            EXPECT_EQ(arcs, static_cast<int>(std::ceil((a1 - a0) / 90.0)));
            for (double t : samples(0, 1, 60)) {
                const glm::dvec3 d = *curve_point(*c, t) - centre;
                EXPECT_NEAR(glm::length(d), 1.5, 1e-12);
                EXPECT_NEAR(glm::dot(d, glm::cross(X, Y)), 0.0, 1e-12);
            }
            for (int k = 0; k <= arcs; ++k) { // exact angles at the joins
                const double a = (a0 + (a1 - a0) * k / arcs) * M_PI / 180;
                const glm::dvec3 want = centre + 1.5 * (std::cos(a) * X + std::sin(a) * Y);
                EXPECT_LT(glm::distance(*curve_point(*c, double(k) / arcs), want), 1e-12);
            }
        }
    }
}

TEST(Primitives, FullCircleAndLine) {
    auto c = full_circle({0, 0, 0}, 2.0, Plane::xy);
    ASSERT_TRUE(c.ok());
    EXPECT_EQ(c->count(), 9);
    EXPECT_EQ(c->points.front(), c->points.back());
    EXPECT_EQ(c->knots, (Knots{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}));
    EXPECT_DOUBLE_EQ(c->weights[1], std::sqrt(0.5));
    // Quarter arcs have exact control points (no sin/cos rounding at multiples of 45 degrees).
    const std::vector<glm::dvec3> square = {{2, 0, 0},  {2, 2, 0},  {0, 2, 0},
                                            {-2, 2, 0}, {-2, 0, 0}, {-2, -2, 0},
                                            {0, -2, 0}, {2, -2, 0}, {2, 0, 0}};
    EXPECT_EQ(c->points, square);
    const Curve l = line_segment({0, 0, 0}, {2, 4, 6});
    ASSERT_TRUE(validate_curve(l).ok());
    for (double t : samples(0, 1, 10))
        EXPECT_LT(glm::distance(*curve_point(l, t), glm::dvec3{2, 4, 6} * t), 1e-15);
}

TEST(Primitives, BadArcsAreSchemaErrors) {
    auto r = circular_arc({0, 0, 0}, 0.0, 0, 90, Plane::xy);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/radius");
    r = circular_arc({0, 0, 0}, 1.0, 90, 90, Plane::xy);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/end");
    r = circular_arc({0, 0, 0}, 1.0, 0, 400, Plane::xy);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/end");
}
