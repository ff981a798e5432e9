// Fitting: interpolation with end derivatives (P&T 9.2.2), surface interpolation (A9.4) and
// least-squares approximation (9.4.1): through the points, with the derivatives asked for, and
// the least-squares fit a true minimiser.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/basis.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/fitting.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

constexpr Parametrization all_modes[] = {Parametrization::chord, Parametrization::centripetal,
                                         Parametrization::uniform};

std::vector<glm::dvec3> random_points(RandomGeometry& g, int count) {
    std::vector<glm::dvec3> pts;
    for (int k = 0; k < count; ++k)
        pts.push_back({g.uniform(-5, 5), g.uniform(-5, 5), g.uniform(-5, 5)});
    return pts;
}

double largest(const std::vector<glm::dvec3>& pts) {
    double m = 1;
    for (const auto& p : pts) m = std::max(m, glm::length(p));
    return m;
}

// Points along a wavy curve: least-squares data that no low-degree curve fits exactly.
std::vector<glm::dvec3> wavy_points(int count) {
    std::vector<glm::dvec3> pts;
    for (int k = 0; k < count; ++k) {
        const double s = static_cast<double>(k) / (count - 1);
        pts.push_back({4 * s, std::sin(7 * s) + 0.3 * std::cos(23 * s), s * s});
    }
    return pts;
}

double sum_of_squares(const Curve& c, const std::vector<glm::dvec3>& pts,
                      const std::vector<double>& t) {
    double sum = 0;
    for (size_t k = 0; k < pts.size(); ++k) {
        const glm::dvec3 d = *curve_point(c, t[k]) - pts[k];
        sum += glm::dot(d, d);
    }
    return sum;
}

} // namespace

TEST(InterpolateEndDerivatives, PassesThroughThePointsWithTheGivenEndDerivatives) {
    RandomGeometry g(9201);
    for (Parametrization mode : all_modes) {
        for (int trial = 0; trial < 40; ++trial) {
            const int count = g.integer(2, 15);
            const auto pts = random_points(g, count);
            const glm::dvec3 d0{g.uniform(-9, 9), g.uniform(-9, 9), g.uniform(-9, 9)};
            const glm::dvec3 d1{g.uniform(-9, 9), g.uniform(-9, 9), g.uniform(-9, 9)};
            const int p = g.integer(2, std::min(6, count + 1));
            auto r = interpolate_curve_with_end_derivatives(pts, p, mode, d0, d1);
            ASSERT_TRUE(r.ok()) << r.error().message;
            const Curve& c = r->curve;
            ASSERT_TRUE(validate_curve(c).ok()) << validate_curve(c).error().message;
            EXPECT_EQ(c.count(), count + 2);
            EXPECT_EQ(c.knots.front(), 0.0);
            EXPECT_EQ(c.knots.back(), 1.0);
            const double scale = largest(pts);
            for (int k = 0; k < count; ++k)
                EXPECT_LT(glm::distance(*curve_point(c, r->params[k]), pts[k]), 1e-12 * scale);
            const auto start = *curve_derivatives(c, 0.0, 1);
            const auto end = *curve_derivatives(c, 1.0, 1);
            EXPECT_LT(glm::distance(start[1], d0), 1e-10 * (scale + glm::length(d0)));
            EXPECT_LT(glm::distance(end[1], d1), 1e-10 * (scale + glm::length(d1)));
        }
    }
}

TEST(InterpolateEndDerivatives, KnotsFollowEquation922) {
    const std::vector<glm::dvec3> pts = {{0, 0, 0}, {1, 1, 0}, {3, 1, 0}, {4, 0, 0}};
    auto r = interpolate_curve_with_end_derivatives(pts, 2, Parametrization::uniform, {1, 0, 0},
                                                    {1, 0, 0});
    ASSERT_TRUE(r.ok());
    // t = 0, 1/3, 2/3, 1; p = 2: interior knots (t_j + t_(j+1)) / 2 for j = 0..2.
    const Knots want = {0, 0, 0, 1.0 / 6, 0.5, 5.0 / 6, 1, 1, 1};
    ASSERT_EQ(r->curve.knots.size(), want.size());
    for (size_t k = 0; k < want.size(); ++k) EXPECT_DOUBLE_EQ(r->curve.knots[k], want[k]);
}

TEST(InterpolateEndDerivatives, TwoPointsMakeTheCubicHermiteBezier) {
    const glm::dvec3 a{0, 0, 0}, b{3, 1, 0}, da{3, 3, 0}, db{0, -3, 3};
    auto r = interpolate_curve_with_end_derivatives({a, b}, 3, Parametrization::chord, da, db);
    ASSERT_TRUE(r.ok());
    const Curve& c = r->curve;
    EXPECT_EQ(c.knots, bezier_knots(3));
    // P1 = P0 + D0 / 3, P2 = P3 - D1 / 3.
    EXPECT_LT(glm::distance(c.points[1], a + da / 3.0), 1e-14);
    EXPECT_LT(glm::distance(c.points[2], b - db / 3.0), 1e-14);
}

TEST(InterpolateEndDerivatives, RefusesDegreeOneAndTooFewPoints) {
    auto r = interpolate_curve_with_end_derivatives({{0, 0, 0}, {1, 0, 0}, {2, 1, 0}}, 1,
                                                    Parametrization::chord, {1, 0, 0}, {1, 0, 0});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::degree);
    EXPECT_EQ(r.error().path, "/degree");
    r = interpolate_curve_with_end_derivatives({{0, 0, 0}, {1, 0, 0}}, 4, Parametrization::chord,
                                               {1, 0, 0}, {1, 0, 0});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::degree);
    r = interpolate_curve_with_end_derivatives({{0, 0, 0}}, 2, Parametrization::chord, {1, 0, 0},
                                               {1, 0, 0});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/points");
    r = interpolate_curve_with_end_derivatives({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}}, 2,
                                               Parametrization::chord, {1, 0, 0}, {1, 0, 0});
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::geometry);
    EXPECT_EQ(r.error().path, "/points/2");
}

TEST(InterpolateSurface, HitsEveryGridPoint) {
    RandomGeometry g(9202);
    for (Parametrization mode : all_modes) {
        for (int trial = 0; trial < 15; ++trial) {
            const int rows = g.integer(2, 9), columns = g.integer(2, 9);
            const auto grid = random_points(g, rows * columns);
            const int p = g.integer(1, std::min(4, rows - 1));
            const int q = g.integer(1, std::min(4, columns - 1));
            auto r = interpolate_surface(grid, rows, columns, p, q, mode);
            ASSERT_TRUE(r.ok()) << r.error().message;
            const Surface& s = r->surface;
            ASSERT_TRUE(validate_surface(s).ok());
            EXPECT_EQ(s.degree_u, p);
            EXPECT_EQ(s.degree_v, q);
            EXPECT_EQ(s.knots_u, averaged_knots(r->u_params, p));
            EXPECT_EQ(s.knots_v, averaged_knots(r->v_params, q));
            const double scale = largest(grid);
            for (int k = 0; k < rows; ++k)
                for (int l = 0; l < columns; ++l) {
                    const glm::dvec3 at = *surface_point(s, r->u_params[k], r->v_params[l]);
                    EXPECT_LT(glm::distance(at, grid[k * columns + l]), 1e-12 * scale)
                        << k << "," << l;
                }
        }
    }
}

TEST(InterpolateSurface, AveragesParametersAndSkipsACollapsedColumn) {
    // Column 0 is one point (a pole): A9.4 leaves it out of the u average. The other two
    // columns have u-lengths 1, 3 and 2, 2: parameters (0, 1/4, 1) and (0, 1/2, 1).
    const std::vector<glm::dvec3> grid = {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, //
                                          {0, 0, 0}, {1, 1, 0}, {2, 2, 0}, //
                                          {0, 0, 0}, {4, 1, 0}, {4, 2, 0}};
    auto r = interpolate_surface(grid, 3, 3, 2, 2, Parametrization::chord);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_DOUBLE_EQ(r->u_params[1], (0.25 + 0.5) / 2);
    for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
            EXPECT_LT(glm::distance(*surface_point(r->surface, r->u_params[k], r->v_params[l]),
                                    grid[k * 3 + l]),
                      1e-12);
}

TEST(InterpolateSurface, RefusesCoincidentRowsAndColumns) {
    std::vector<glm::dvec3> grid = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                                    {0, 1, 0}, {1, 1, 0}, {0, 3, 0}, {1, 3, 0}};
    auto r = interpolate_surface(grid, 4, 2, 2, 1, Parametrization::chord);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::geometry);
    EXPECT_EQ(r.error().path, "/grid/2");
    grid = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 1, 0}};
    r = interpolate_surface(grid, 2, 3, 1, 1, Parametrization::centripetal);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/grid/0/2");
    grid.assign(6, glm::dvec3(2, 2, 2));
    r = interpolate_surface(grid, 2, 3, 1, 1, Parametrization::chord);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().path, "/grid");
    r = interpolate_surface(grid, 2, 3, 1, 3, Parametrization::uniform);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::degree);
    EXPECT_EQ(r.error().path, "/degree/1");
    r = interpolate_surface(grid, 1, 6, 1, 1, Parametrization::uniform);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/grid");
}

TEST(Approximate, IsTheLeastSquaresMinimiserWithFixedEnds) {
    RandomGeometry g(9203);
    for (Parametrization mode : all_modes) {
        for (int trial = 0; trial < 20; ++trial) {
            const int total = g.integer(6, 40);
            const auto pts = wavy_points(total);
            const int p = g.integer(1, 4);
            const int count = g.integer(p + 1, std::min(total, p + 12));
            auto r = approximate_curve(pts, p, count, mode);
            ASSERT_TRUE(r.ok()) << r.error().message;
            const Curve& c = r->curve;
            ASSERT_TRUE(validate_curve(c).ok());
            ASSERT_EQ(c.count(), count);
            EXPECT_EQ(c.points.front(), pts.front());
            EXPECT_EQ(c.points.back(), pts.back());
            // The gradient of sum |C(t_k) - Q_k|^2 with respect to each interior control point,
            // sum_k N_i(t_k) (C(t_k) - Q_k), vanishes.
            std::vector<glm::dvec3> gradient(count, glm::dvec3(0));
            for (int k = 0; k < total; ++k) {
                const auto N = all_basis(c.knots, p, count, r->params[k])[0];
                const glm::dvec3 residual = *curve_point(c, r->params[k]) - pts[k];
                for (int i = 0; i < count; ++i) gradient[i] += N[i] * residual;
            }
            for (int i = 1; i + 1 < count; ++i) EXPECT_LT(glm::length(gradient[i]), 1e-10) << i;
            // Moving any interior control point makes the fit worse.
            const double best = sum_of_squares(c, pts, r->params);
            for (int i = 1; i + 1 < count; ++i) {
                Curve moved = c;
                moved.points[i] +=
                    glm::dvec3(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-1, 1)) * 1e-3;
                EXPECT_GT(sum_of_squares(moved, pts, r->params), best) << i;
            }
            // The reported errors are those of the curve at the parameters.
            double max_error = 0, sum = 0;
            for (int k = 0; k < total; ++k) {
                const double e = glm::distance(*curve_point(c, r->params[k]), pts[k]);
                max_error = std::max(max_error, e);
                sum += e * e;
            }
            EXPECT_DOUBLE_EQ(r->max_error, max_error);
            EXPECT_NEAR(r->rms_error, std::sqrt(sum / total), 1e-15);
        }
    }
}

TEST(Approximate, KnotsFollowEquation969) {
    const auto pts = wavy_points(10);
    auto r = approximate_curve(pts, 3, 6, Parametrization::uniform);
    ASSERT_TRUE(r.ok());
    // m + 1 = 10, n + 1 = 6, p = 3: d = 10 / 3; j = 1: i = 3, alpha = 1/3; j = 2: i = 6,
    // alpha = 2/3; t_k = k / 9.
    const Knots& U = r->curve.knots;
    ASSERT_EQ(U.size(), 10u);
    const double d = 10.0 / 3;
    EXPECT_NEAR(U[4], (1 - (d - 3)) * 2.0 / 9 + (d - 3) * 3.0 / 9, 1e-15);
    EXPECT_NEAR(U[5], (1 - (2 * d - 6)) * 5.0 / 9 + (2 * d - 6) * 6.0 / 9, 1e-15);
}

TEST(Approximate, AsManyControlPointsAsPointsInterpolates) {
    const auto pts = wavy_points(9);
    auto r = approximate_curve(pts, 3, 9, Parametrization::chord);
    ASSERT_TRUE(r.ok());
    EXPECT_LT(r->max_error, 1e-12);
    auto bezier = approximate_curve(pts, 3, 4, Parametrization::chord);
    ASSERT_TRUE(bezier.ok());
    EXPECT_EQ(bezier->curve.knots, bezier_knots(3));
    EXPECT_GT(bezier->max_error, r->max_error);
    auto line = approximate_curve(pts, 1, 2, Parametrization::chord);
    ASSERT_TRUE(line.ok());
    EXPECT_EQ(line->curve.points.size(), 2u);
}

TEST(Approximate, RefusesCountsOutsideTheirRange) {
    const auto pts = wavy_points(6);
    auto r = approximate_curve(pts, 3, 7, Parametrization::chord);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/count");
    r = approximate_curve(pts, 3, 3, Parametrization::chord);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::degree);
    EXPECT_EQ(r.error().path, "/count");
    r = approximate_curve(pts, 6, 6, Parametrization::chord);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::degree);
    EXPECT_EQ(r.error().path, "/degree");
    r = approximate_curve({{1, 1, 1}}, 1, 2, Parametrization::chord);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::schema);
    EXPECT_EQ(r.error().path, "/points");
}

namespace {

std::vector<glm::dvec3> wavy_grid(int rows, int columns) {
    std::vector<glm::dvec3> grid;
    for (int k = 0; k < rows; ++k)
        for (int l = 0; l < columns; ++l)
            grid.emplace_back(k * 0.3 + 0.02 * std::sin(l), l * 0.25,
                              std::sin(0.7 * k) * std::cos(0.5 * l) + 0.03 * ((k * 7 + l) % 3));
    return grid;
}

} // namespace

TEST(ApproximateSurface, InteriorGradientVanishesAndCornersAreKept) {
    RandomGeometry g(4411);
    for (int trial = 0; trial < 12; ++trial) {
        const int rows = g.integer(5, 14), columns = g.integer(5, 14);
        const auto grid = wavy_grid(rows, columns);
        const int p = g.integer(1, 3), q = g.integer(1, 3);
        const int cu = g.integer(p + 1, rows), cv = g.integer(q + 1, columns);
        auto r = approximate_surface(grid, rows, columns, p, q, cu, cv, Parametrization::chord);
        ASSERT_TRUE(r.ok()) << r.error().message;
        const Surface& s = r->surface;
        ASSERT_TRUE(validate_surface(s).ok());
        EXPECT_EQ(s.point(0, 0), grid.front());
        EXPECT_EQ(s.point(cu - 1, cv - 1), grid.back());
        // d/dP_ij of sum |S(u_k, v_l) - Q_kl|^2 for the interior control points vanishes.
        double worst = 0, sum = 0, max_error = 0;
        std::vector<glm::dvec3> gradient(static_cast<size_t>(cu) * cv, glm::dvec3(0));
        for (int k = 0; k < rows; ++k)
            for (int l = 0; l < columns; ++l) {
                const auto Nu = all_basis(s.knots_u, p, cu, r->u_params[k])[0];
                const auto Nv = all_basis(s.knots_v, q, cv, r->v_params[l])[0];
                const glm::dvec3 residual = *surface_point(s, r->u_params[k], r->v_params[l]) -
                                            grid[static_cast<size_t>(k) * columns + l];
                max_error = std::max(max_error, glm::length(residual));
                sum += glm::dot(residual, residual);
                for (int i = 0; i < cu; ++i)
                    for (int j = 0; j < cv; ++j)
                        gradient[static_cast<size_t>(i) * cv + j] += Nu[i] * Nv[j] * residual;
            }
        for (int i = 1; i + 1 < cu; ++i)
            for (int j = 1; j + 1 < cv; ++j)
                worst = std::max(worst, glm::length(gradient[static_cast<size_t>(i) * cv + j]));
        EXPECT_LT(worst, 1e-10) << rows << "x" << columns << " p" << p << " q" << q;
        EXPECT_DOUBLE_EQ(r->max_error, max_error);
        EXPECT_NEAR(r->rms_error, std::sqrt(sum / (rows * columns)), 1e-15);
    }
}

TEST(ApproximateSurface, FullCountsInterpolateAndBadCountsAreRefused) {
    const auto grid = wavy_grid(6, 7);
    auto r = approximate_surface(grid, 6, 7, 3, 2, 6, 7, Parametrization::centripetal);
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_LT(r->max_error, 1e-12);
    auto few = approximate_surface(grid, 6, 7, 3, 2, 3, 5, Parametrization::chord);
    ASSERT_FALSE(few.ok());
    EXPECT_EQ(few.error().code, ErrorCode::degree);
    EXPECT_EQ(few.error().path, "/count/0");
    auto many = approximate_surface(grid, 6, 7, 3, 2, 5, 8, Parametrization::chord);
    ASSERT_FALSE(many.ok());
    EXPECT_EQ(many.error().code, ErrorCode::schema);
    EXPECT_EQ(many.error().path, "/count/1");
    auto degree = approximate_surface(grid, 6, 7, 6, 2, 6, 5, Parametrization::chord);
    ASSERT_FALSE(degree.ok());
    EXPECT_EQ(degree.error().path, "/degree/0");
}
