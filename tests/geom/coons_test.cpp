// The Coons patch reproduces its four boundaries and refuses open corners and rational blends.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/coons.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/validate.hpp"

using namespace isoparm::geom;

namespace {

Curve bspline(int p, std::vector<glm::dvec3> points, double a = 0, double b = 1) {
    Curve c;
    c.degree = p;
    c.points = std::move(points);
    c.weights.assign(c.points.size(), 1.0);
    c.knots = clamped_uniform_knots(c.count(), p, a, b);
    return c;
}

// A curved quadrilateral: cubic bottom, quadratic top, a line on the left, a 2-span cubic on
// the right with its own domain [2, 5].
std::array<Curve, 4> network() {
    const glm::dvec3 P00(0, 0, 0), P10(3, 0, 1), P01(0, 2, 0), P11(3, 2, -1);
    return {bspline(3, {P00, {1, -0.5, 1}, {2, 0.5, 2}, P10}),
            bspline(2, {P01, {1.5, 3, 0.5}, P11}), bspline(1, {P00, P01}),
            bspline(3, {P10, {3.5, 0.4, 0.5}, {3.2, 1, 0}, {2.7, 1.5, -0.5}, P11}, 2, 5)};
}

double param_on(const Curve& c, double s) { // s in [0, 1] mapped to the curve's domain
    const Interval d = domain(c);
    return d.lo + s * (d.hi - d.lo);
}

TEST(Coons, ReproducesItsFourBoundaries) {
    const auto c = network();
    auto s = coons(c);
    ASSERT_TRUE(s.ok()) << s.error().message;
    ASSERT_TRUE(validate_surface(*s).ok());
    for (double t = 0; t <= 1.0; t += 0.05) {
        EXPECT_LT(glm::length(*surface_point(*s, t, 0) - *curve_point(c[0], param_on(c[0], t))),
                  1e-13);
        EXPECT_LT(glm::length(*surface_point(*s, t, 1) - *curve_point(c[1], param_on(c[1], t))),
                  1e-13);
        EXPECT_LT(glm::length(*surface_point(*s, 0, t) - *curve_point(c[2], param_on(c[2], t))),
                  1e-13);
        EXPECT_LT(glm::length(*surface_point(*s, 1, t) - *curve_point(c[3], param_on(c[3], t))),
                  1e-13);
    }
    // The interior is the blend: S = R_u + R_v - T at an inside point.
    const double u = 0.3, v = 0.6;
    const glm::dvec3 Ru = (1 - v) * *curve_point(c[0], u) + v * *curve_point(c[1], u);
    const glm::dvec3 Rv =
        (1 - u) * *curve_point(c[2], v) + u * *curve_point(c[3], param_on(c[3], v));
    const glm::dvec3 T = (1 - u) * (1 - v) * c[0].points.front() +
                         u * (1 - v) * c[0].points.back() + (1 - u) * v * c[1].points.front() +
                         u * v * c[1].points.back();
    EXPECT_LT(glm::length(*surface_point(*s, u, v) - (Ru + Rv - T)), 1e-13);
}

TEST(Coons, AnOpenCornerIsRefusedAtTheCurve) {
    auto c = network();
    c[3].points.back() += glm::dvec3(0, 0, 1e-6);
    auto s = coons(c);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::geometry);
    EXPECT_EQ(s.error().path, "/curves/3");
    EXPECT_NE(s.error().message.find("S(1, 1)"), std::string::npos) << s.error().message;
}

TEST(Coons, RationalBoundariesNeedEqualWeights) {
    auto c = network();
    c[1].type = SplineType::nurbs;
    c[1].weights = {2, 2, 2}; // equal weights: the same polynomial curve
    EXPECT_TRUE(coons(c).ok());
    c[1].weights = {1, 2, 1};
    auto s = coons(c);
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::weights);
    EXPECT_EQ(s.error().path, "/curves/1");
}

// The size caps are checked before any of the work: boundaries of 1,501 points make a result of
// at least 1,501 x 1,501, refused at once as `limit` (it took 9.8 s to be refused after the
// work), even where a corner is also open (which was found first, then the work done).
TEST(Coons, ACapThatTheBoundariesPassIsRefusedBeforeTheWork) {
    std::vector<glm::dvec3> row, column;
    for (int k = 0; k <= 1500; ++k) {
        row.push_back({k / 750.0, 0, 0});
        column.push_back({0, k / 750.0, 0});
    }
    std::vector<glm::dvec3> top = row, right = column;
    for (auto& p : top) p.y = 2;
    for (auto& p : right) p.x = 2;
    right.back().z = 1; // the corner S(1, 1) is open
    auto s = coons(
        {bspline(1500, row), bspline(1500, top), bspline(1500, column), bspline(1500, right)});
    ASSERT_FALSE(s.ok());
    EXPECT_EQ(s.error().code, ErrorCode::limit) << s.error().message;
    EXPECT_NE(s.error().message.find("1501 x 1501"), std::string::npos) << s.error().message;
}

} // namespace
