// Curvature of implicit surfaces from f's gradient and Hessian (Goldman 2005): known values on
// spheres, cylinders, a hyperboloid and a paraboloid, in the convention of spline surfaces.
#include <gtest/gtest.h>

#include <cmath>

#include "core/geom/implicit/curvature.hpp"
#include "core/geom/implicit/expression.hpp"

using namespace isoparm::geom;
using namespace isoparm::geom::implicit;

namespace {

Program compiled(const char* text, const std::vector<std::string>& names = {}) {
    auto p = compile(text, names);
    EXPECT_TRUE(p.ok()) << text;
    return std::move(p).value();
}

} // namespace

TEST(ImplicitCurvature, SphereOfRadiusTwoEverywhere) {
    const Program f = compiled("x^2 + y^2 + z^2 - 4");
    for (const glm::dvec3 p :
         {glm::dvec3(2, 0, 0), glm::dvec3(0, -2, 0), glm::dvec3(1, 1, std::sqrt(2.0))}) {
        const auto k = implicit_curvature(f, p);
        ASSERT_TRUE(k);
        EXPECT_NEAR(k->gaussian, 0.25, 1e-8);
        // The normal grad f points out: the spline convention's sign (mean = -1/r).
        EXPECT_NEAR(k->mean, -0.5, 1e-8);
        EXPECT_NEAR(k->k1, -0.5, 1e-4);
        EXPECT_NEAR(k->k2, -0.5, 1e-4);
    }
}

TEST(ImplicitCurvature, CylinderHyperboloidParaboloid) {
    const auto cyl = implicit_curvature(compiled("x^2 + y^2 - 9"), {3, 0, 5});
    ASSERT_TRUE(cyl);
    EXPECT_NEAR(cyl->gaussian, 0, 1e-8);
    EXPECT_NEAR(cyl->mean, -1.0 / 6.0, 1e-8);
    EXPECT_NEAR(cyl->k2, -1.0 / 3.0, 1e-7);
    EXPECT_NEAR(cyl->k1, 0, 1e-7);
    // The hyperboloid of one sheet x^2 + y^2 - z^2 = 1 at its waist: a saddle, K = -1, H = 0
    // (Gaussian curvature used to be hatched as undefined on it).
    const auto hyp = implicit_curvature(compiled("x^2 + y^2 - z^2 - 1"), {1, 0, 0});
    ASSERT_TRUE(hyp);
    EXPECT_NEAR(hyp->gaussian, -1, 1e-8);
    EXPECT_NEAR(hyp->mean, 0, 1e-8);
    EXPECT_NEAR(hyp->k1, 1, 1e-7);
    EXPECT_NEAR(hyp->k2, -1, 1e-7);
    // Away from the waist: K = -1 / (1 + 2 z^2)^2 on x^2 + y^2 = 1 + z^2.
    const double z = 1.5, r = std::sqrt(1 + z * z);
    const auto far = implicit_curvature(compiled("x^2 + y^2 - z^2 - 1"), {r, 0, z});
    ASSERT_TRUE(far);
    EXPECT_NEAR(far->gaussian, -1 / std::pow(1 + 2 * z * z, 2), 1e-8);
    // z = x^2 + y^2 at its vertex: k1 = k2 = 2 in size, K = 4.
    const auto par = implicit_curvature(compiled("x^2 + y^2 - z"), {0, 0, 0});
    ASSERT_TRUE(par);
    EXPECT_NEAR(par->gaussian, 4, 1e-7);
    EXPECT_NEAR(std::abs(par->mean), 2, 1e-7);
}

TEST(ImplicitCurvature, ParametersAndTheValueOfAKind) {
    const Program f = compiled("x^2 + y^2 + z^2 - r^2", {"r"});
    const double r = 0.5;
    EXPECT_NEAR(implicit_curvature_value(f, {0, 0, 0.5}, CurvatureKind::gaussian, &r), 4, 1e-7);
    EXPECT_NEAR(implicit_curvature_value(f, {0, 0.5, 0}, CurvatureKind::mean, &r), -2, 1e-7);
    EXPECT_NEAR(implicit_curvature_value(f, {0.5, 0, 0}, CurvatureKind::k_max, &r), -2, 1e-3);
}

TEST(ImplicitCurvature, UndefinedWhereTheGradientVanishes) {
    // The cone's apex: no normal.
    const Program f = compiled("x^2 + y^2 - z^2");
    EXPECT_FALSE(implicit_curvature(f, {0, 0, 0}));
    EXPECT_TRUE(std::isnan(implicit_curvature_value(f, {0, 0, 0}, CurvatureKind::mean)));
}
