// The Fit panel's fitting: interpolation passes through its points, least squares reports the
// distances it really has, a grid is interpolated, and refusals keep the geometry's paths.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "core/doc/fit.hpp"
#include "core/geom/evaluate.hpp"

using namespace isoparm;
using namespace isoparm::doc;

namespace {

std::vector<glm::dvec3> wave(int n) {
    std::vector<glm::dvec3> pts;
    for (int k = 0; k < n; ++k) {
        const double x = k * 0.4;
        pts.emplace_back(x, std::sin(2 * x) + 0.05 * (k % 3), 0);
    }
    return pts;
}

TEST(FitCurve, InterpolationPassesThroughEveryPoint) {
    const auto pts = wave(9);
    FitSettings s;
    auto fit = fit_curve(pts, s, "fit", CurvePlane::xy);
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    const geom::Curve& c = fit->object.curve_object()->curve;
    ASSERT_EQ(fit->errors.size(), pts.size());
    for (std::size_t k = 0; k < pts.size(); ++k) {
        const glm::dvec3 p = *geom::curve_point(c, fit->params[k]);
        EXPECT_LT(glm::distance(p, pts[k]), 1e-12 * (1 + glm::length(pts[k]))) << k;
    }
    EXPECT_LT(fit->max_error, 1e-12);
    EXPECT_EQ(fit->object.curve_object()->knot_mode, CurveKnotMode::custom);
}

TEST(FitCurve, LeastSquaresReportsItsRealDistances) {
    const auto pts = wave(20);
    FitSettings s;
    s.method = FitMethod::approximate;
    s.count = 7;
    auto fit = fit_curve(pts, s, "fit", CurvePlane::xy);
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    const geom::Curve& c = fit->object.curve_object()->curve;
    EXPECT_EQ(c.count(), 7);
    double max = 0, sum = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
        const double e = glm::distance(*geom::curve_point(c, fit->params[k]), pts[k]);
        EXPECT_DOUBLE_EQ(fit->errors[k], e);
        max = std::max(max, e);
        sum += e * e;
    }
    EXPECT_DOUBLE_EQ(fit->max_error, max);
    EXPECT_NEAR(fit->rms_error, std::sqrt(sum / pts.size()), 1e-15);
    EXPECT_GT(fit->max_error, 0);
    // The ends are kept exactly (9.4.1).
    EXPECT_EQ(fit->errors.front(), 0);
    EXPECT_EQ(fit->errors.back(), 0);
}

TEST(FitCurve, RefusalsKeepTheGeometrysPaths) {
    FitSettings s;
    s.degree = 5;
    auto few = fit_curve(wave(3), s, "fit", CurvePlane::xy);
    ASSERT_FALSE(few.ok());
    EXPECT_EQ(few.error().path, "/degree");
    FitSettings quadratic;
    quadratic.degree = 2;
    auto same = fit_curve({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}, quadratic, "fit", CurvePlane::xy);
    ASSERT_FALSE(same.ok());
    EXPECT_EQ(same.error().code, geom::ErrorCode::geometry) << same.error().message;
    s = {};
    s.method = FitMethod::approximate;
    s.count = 40;
    auto many = fit_curve(wave(10), s, "fit", CurvePlane::xy);
    ASSERT_FALSE(many.ok());
    EXPECT_EQ(many.error().path, "/count");
}

TEST(FitGrid, InterpolatesOrFitsByLeastSquares) {
    std::vector<glm::dvec3> grid;
    for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 5; ++l) grid.emplace_back(k, l, std::sin(k + 0.5 * l));
    FitSettings s;
    s.degree = 2;
    s.degree_v = 3;
    auto fit = fit_grid(grid, 4, 5, s, "grid fit");
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    EXPECT_LT(fit->max_error, 1e-12);
    EXPECT_EQ(fit->object.surface()->degree_u, 2);
    EXPECT_EQ(fit->object.surface()->degree_v, 3);
    s.method = FitMethod::approximate;
    s.count = 3;
    s.count_v = 4;
    auto least = fit_grid(grid, 4, 5, s, "grid fit");
    ASSERT_TRUE(least.ok()) << least.error().message;
    EXPECT_EQ(least->object.surface()->n_u, 3);
    EXPECT_EQ(least->object.surface()->n_v, 4);
    EXPECT_GT(least->max_error, 0);
    EXPECT_GE(least->max_error, least->rms_error);
    s.count_v = 6;
    auto refused = fit_grid(grid, 4, 5, s, "grid fit");
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().path, "/count/1");
}

} // namespace
