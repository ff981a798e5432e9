// The Gordon surface interpolates its whole network, and reproduces a bicubic from its
// isocurves.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/gordon.hpp"
#include "core/geom/knots.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;

namespace {

Surface random_bicubic(unsigned seed) {
    isoparm::testing::RandomGeometry g(seed);
    Surface s = g.surface(3, 3, 4, 4, false);
    s.type = SplineType::bezier;
    s.knots_u = s.knots_v = clamped_uniform_knots(4, 3);
    return s;
}

// The isocurve of constant v (dir u) or constant u (dir v): a Bezier curve whose control
// points are the other direction's lines evaluated at the parameter.
Curve isocurve(const Surface& s, Dir along, double at) {
    Curve c;
    c.type = SplineType::bezier;
    c.degree = s.degree(along);
    c.knots = s.knots(along);
    const Dir across = along == Dir::u ? Dir::v : Dir::u;
    for (int i = 0; i < s.count(along); ++i)
        c.points.push_back(*curve_point(surface_line(s, across, i), at));
    c.weights.assign(c.points.size(), 1.0);
    return c;
}

TEST(Gordon, ReproducesABicubicFromFourByFourIsocurves) {
    const Surface S = random_bicubic(31);
    const std::vector<double> vs = {0, 0.3, 0.65, 1}, us = {0, 0.4, 0.8, 1};
    std::vector<Curve> u_curves, v_curves;
    for (double v : vs) u_curves.push_back(isocurve(S, Dir::u, v));
    for (double u : us) v_curves.push_back(isocurve(S, Dir::v, u));
    auto g = gordon(u_curves, v_curves);
    ASSERT_TRUE(g.ok()) << g.error().message;
    for (int k = 0; k < 4; ++k) {
        EXPECT_NEAR(g->v_params[k], vs[k], 1e-10);
        EXPECT_NEAR(g->u_params[k], us[k], 1e-10);
    }
    for (double u : {0.1, 0.5, 0.93})
        for (double v : {0.05, 0.45, 0.8})
            EXPECT_LT(glm::length(*surface_point(g->surface, u, v) - *surface_point(S, u, v)),
                      1e-9);
}

TEST(Gordon, InterpolatesEveryCurveOfAThreeByFiveNetwork) {
    const Surface S = random_bicubic(32);
    const std::vector<double> vs = {0.6, 0, 1}, us = {0, 0.2, 0.5, 0.75, 1}; // v out of order
    std::vector<Curve> u_curves, v_curves;
    for (double v : vs) u_curves.push_back(isocurve(S, Dir::u, v));
    for (double u : us) v_curves.push_back(isocurve(S, Dir::v, u));
    auto g = gordon(u_curves, v_curves);
    ASSERT_TRUE(g.ok()) << g.error().message;
    EXPECT_NEAR(g->v_params[0], 0.6, 1e-10); // the given order is kept in the answer
    for (double t = 0; t <= 1; t += 0.125) {
        for (std::size_t k = 0; k < vs.size(); ++k)
            EXPECT_LT(glm::length(*surface_point(g->surface, t, g->v_params[k]) -
                                  *curve_point(u_curves[k], t)),
                      1e-9);
        for (std::size_t l = 0; l < us.size(); ++l)
            EXPECT_LT(glm::length(*surface_point(g->surface, g->u_params[l], t) -
                                  *curve_point(v_curves[l], t)),
                      1e-9);
    }
}

TEST(Gordon, RefusesCurvesThatDoNotMeet) {
    const Surface S = random_bicubic(33);
    std::vector<Curve> u_curves = {isocurve(S, Dir::u, 0), isocurve(S, Dir::u, 1)};
    std::vector<Curve> v_curves = {isocurve(S, Dir::v, 0), isocurve(S, Dir::v, 1)};
    for (glm::dvec3& p : v_curves[1].points) p.z += 0.5;
    auto g = gordon(u_curves, v_curves);
    ASSERT_FALSE(g.ok());
    EXPECT_EQ(g.error().code, ErrorCode::geometry);
    EXPECT_EQ(g.error().path, "/v_curves/1");
    EXPECT_EQ(gordon({u_curves[0]}, v_curves).error().path, "/u_curves");
}

// The size caps are checked before any of the work: curves of 1,501 points make a result of
// at least 1,501 x 1,501, refused at once as `limit` (it took 17.8 s to be refused after the
// crossings were searched and the surfaces built), even where the curves do not meet.
TEST(Gordon, ACapThatTheCurvesPassIsRefusedBeforeTheWork) {
    auto line = [](glm::dvec3 a, glm::dvec3 b) {
        Curve c;
        c.degree = 1500;
        for (int k = 0; k <= 1500; ++k) c.points.push_back(a + (b - a) * (k / 1500.0));
        c.weights.assign(c.points.size(), 1.0);
        c.knots = clamped_uniform_knots(c.count(), c.degree, 0, 1);
        return c;
    };
    const std::vector<Curve> u_curves = {line({0, 0, 0}, {2, 0, 0}), line({0, 2, 0}, {2, 2, 0})};
    const std::vector<Curve> v_curves = {line({0, 0, 0}, {0, 2, 0}), line({2, 0, 1}, {2, 2, 1})};
    auto g = gordon(u_curves, v_curves);
    ASSERT_FALSE(g.ok());
    EXPECT_EQ(g.error().code, ErrorCode::limit) << g.error().message;
    EXPECT_NE(g.error().message.find("1501 x 1501"), std::string::npos) << g.error().message;
}

} // namespace
