// Extending a B-spline or NURBS past its domain: unchanged on the old domain, the end pieces'
// polynomials (rational functions) carried on outside it, rational arcs stay on their circle.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "core/geom/deboor.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/extend.hpp"
#include "core/geom/knots.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

double gap(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(a - b) / std::max(1.0, glm::length(b));
}

// The end piece's own polynomial at t (de Boor's triangle on that span with t everywhere),
// in homogeneous space: the continuation the extension must equal.
glm::dvec3 piece_at(const Curve& c, int span, double t) {
    std::vector<HPoint> Pw;
    for (int i = 0; i < c.count(); ++i) Pw.push_back(c.hpoint(i));
    const HPoint h = deboor_polar(c.knots, c.degree, Pw, span, std::vector<double>(c.degree, t))
                         .levels.back()[0];
    return glm::dvec3(h) / h.w;
}

TEST(ExtendDomain, CubicBezierFollowsItsBernsteinPolynomialOutside) {
    Curve c;
    c.degree = 3;
    c.knots = bezier_knots(3);
    c.points = {{0, 0, 0}, {1, 2, 0}, {3, -1, 1}, {4, 1, 2}};
    c.weights = {1, 1, 1, 1};
    const Expected<Curve> e = extend_domain(c, {-0.5, 1.5});
    ASSERT_TRUE(e) << e.error().message;
    EXPECT_EQ(domain(*e).lo, -0.5);
    EXPECT_EQ(domain(*e).hi, 1.5);
    for (double t = -0.5; t <= 1.5; t += 0.05) {
        const double s = 1 - t;
        const glm::dvec3 bernstein = s * s * s * c.points[0] + 3 * s * s * t * c.points[1] +
                                     3 * s * t * t * c.points[2] + t * t * t * c.points[3];
        EXPECT_LT(gap(*curve_point(*e, t), bernstein), 1e-13) << t;
    }
}

TEST(ExtendDomain, RandomSplinesKeepTheirDomainAndContinueTheirEndPieces) {
    RandomGeometry g(41);
    for (const bool rational : {false, true})
        for (int p = 1; p <= 5; ++p) {
            Curve c = g.curve(p, p + 4, rational);
            // Weights near 1: wilder ones may need a non-positive weight to go on (refused).
            for (double& w : c.weights) w = rational ? g.uniform(0.8, 1.25) : 1.0;
            const Interval d = domain(c);
            const double w = d.hi - d.lo;
            const Interval to{d.lo - 0.1 * w, d.hi + 0.07 * w};
            const Expected<Curve> e = extend_domain(c, to);
            ASSERT_TRUE(e) << e.error().message;
            ASSERT_EQ(e->count(), c.count());
            for (int k = 0; k <= 100; ++k) {
                const double t = d.lo + w * k / 100;
                EXPECT_LT(gap(*curve_point(*e, t), *curve_point(c, t)), 1e-11) << p << " " << t;
            }
            const int first = find_span(c.knots, p, c.count(), d.lo);
            const int last = find_span(c.knots, p, c.count(), d.hi);
            for (int k = 0; k <= 10; ++k) {
                const double before = to.lo + (d.lo - to.lo) * k / 10;
                const double after = d.hi + (to.hi - d.hi) * k / 10;
                EXPECT_LT(gap(*curve_point(*e, before), piece_at(c, first, before)), 1e-11) << p;
                EXPECT_LT(gap(*curve_point(*e, after), piece_at(c, last, after)), 1e-11) << p;
            }
            // The interior is untouched: control points p .. n - p - 1 and the interior knots.
            for (int i = p; i < c.count() - p; ++i) EXPECT_EQ(e->points[i], c.points[i]);
            for (int k = p + 1; k < c.count(); ++k) EXPECT_EQ(e->knots[k], c.knots[k]);
        }
}

TEST(ExtendDomain, AQuarterCircleContinuesOnItsCircle) {
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 2;
    c.knots = bezier_knots(2);
    c.points = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    c.weights = {1, std::sqrt(0.5), 1};
    const Expected<Curve> e = extend_domain(c, {-0.3, 1.4});
    ASSERT_TRUE(e) << e.error().message;
    for (double t = -0.3; t <= 1.4; t += 0.01)
        EXPECT_NEAR(glm::length(*curve_point(*e, t)), 1.0, 1e-13) << t;
    // Past the quarter: the arc goes on beyond (0, 1) into x < 0.
    EXPECT_LT(curve_point(*e, 1.4)->x, -0.1);
}

TEST(ExtendDomain, SurfacesExtendInBothDirections) {
    // A bilinear patch (a plane as a 2 x 2 B-spline, as hammer.iges writes them) and a
    // quarter cylinder of radius 2 along z.
    Surface plane;
    plane.knots_u = bezier_knots(1, 0, 1.4);
    plane.knots_v = bezier_knots(1, 0, 1.8);
    plane.n_u = plane.n_v = 2;
    plane.points = {{0, 0, 0}, {0, 1800, 0}, {1400, 0, 5}, {1400, 1800, 5}};
    plane.weights = {1, 1, 1, 1};
    const Expected<Surface> p = extend_domain(plane, {{-0.01, 1.4}, {-0.02, 1.81}});
    ASSERT_TRUE(p) << p.error().message;
    for (const glm::dvec2 uv : {glm::dvec2(-0.01, -0.02), glm::dvec2(0.7, 1.81), glm::dvec2(1, 1)})
        EXPECT_LT(gap(*surface_point(*p, uv.x, uv.y), {1000 * uv.x, 1000 * uv.y, 5 / 1.4 * uv.x}),
                  1e-13);

    Surface cyl;
    cyl.type = SplineType::nurbs;
    cyl.degree_u = 2;
    cyl.knots_u = bezier_knots(2);
    cyl.knots_v = bezier_knots(1);
    cyl.n_u = 3;
    cyl.n_v = 2;
    const double h = std::sqrt(0.5);
    cyl.points = {{2, 0, 0}, {2, 0, 3}, {2, 2, 0}, {2, 2, 3}, {0, 2, 0}, {0, 2, 3}};
    cyl.weights = {1, 1, h, h, 1, 1};
    const Expected<Surface> e = extend_domain(cyl, {{-0.2, 1.2}, {-0.5, 1.5}});
    ASSERT_TRUE(e) << e.error().message;
    EXPECT_EQ(e->type, SplineType::nurbs);
    for (double u = -0.2; u <= 1.2; u += 0.1)
        for (double v = -0.5; v <= 1.5; v += 0.25) {
            const glm::dvec3 q = *surface_point(*e, u, v);
            EXPECT_NEAR(std::hypot(q.x, q.y), 2.0, 1e-13) << u << " " << v;
            if (u >= 0 && u <= 1 && v >= 0 && v <= 1) {
                EXPECT_LT(gap(q, *surface_point(cyl, u, v)), 1e-14);
            }
        }
    EXPECT_NEAR(surface_point(*e, 0.5, -0.5)->z, -1.5, 1e-13);
}

TEST(ExtendDomain, RefusesWhatItCannotDo) {
    RandomGeometry g(42);
    const Curve unclamped = g.curve(3, 7, false, false);
    const Expected<Curve> a = extend_domain(unclamped, {-10, 10});
    ASSERT_FALSE(a);
    EXPECT_EQ(a.error().code, isoparm::geom::ErrorCode::schema);
    const Curve c = g.curve(3, 7, false);
    const Interval d = domain(c);
    const Expected<Curve> b = extend_domain(c, {d.lo + 0.01, d.hi});
    ASSERT_FALSE(b);
    EXPECT_EQ(b.error().code, isoparm::geom::ErrorCode::domain);
    EXPECT_NE(b.error().message.find("must be finite and hold the domain"), std::string::npos);
    EXPECT_FALSE(extend_domain(c, {-INFINITY, d.hi}));
    // A weight that falls through zero: w(t) = 1 - 0.75 t reaches 0 at t = 4/3.
    Curve fading;
    fading.type = SplineType::nurbs;
    fading.degree = 1;
    fading.knots = bezier_knots(1);
    fading.points = {{0, 0, 0}, {1, 0, 0}};
    fading.weights = {1, 0.25};
    const Expected<Curve> f = extend_domain(fading, {0, 2});
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().code, isoparm::geom::ErrorCode::weights);
}

} // namespace
