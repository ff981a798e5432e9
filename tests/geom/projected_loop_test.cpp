// Trim loops from planar curves projected onto surfaces: exact cases on planes, the projection
// property on a curved surface, kinks kept, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/primitives.hpp"
#include "core/geom/trim/projected_loop.hpp"
#include "core/geom/trim/trim_area.hpp"
#include "core/geom/trim/trim_flatten.hpp"
#include "core/geom/trim/trim_validate.hpp"

using namespace isoparm::geom;

namespace {

// The plane z = h(x, y) = 0.1 x over [0, w] x [0, h] as a bilinear patch on [0, 1]^2, so a
// point (x, y) seen along z lies at (u, v) = (x / w, y / h).
Surface tilted_plane(double w, double h) {
    Surface s;
    s.degree_u = s.degree_v = 1;
    s.n_u = s.n_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, h, 0}, {w, 0, 0.1 * w}, {w, h, 0.1 * w}};
    s.weights = {1, 1, 1, 1};
    return s;
}

// A bicubic hill over [0, 2] x [0, 2] whose parameters are not x and y (the columns bunch up).
Surface hill() {
    Surface s;
    s.degree_u = s.degree_v = 3;
    s.n_u = s.n_v = 6;
    s.knots_u = clamped_uniform_knots(6, 3);
    s.knots_v = clamped_uniform_knots(6, 3);
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const double x = 2.0 * std::pow(i / 5.0, 1.4), y = 2.0 * j / 5.0;
            s.points.push_back({x, y, 0.5 * std::sin(1.3 * i) * std::cos(0.8 * j)});
            s.weights.push_back(1);
        }
    return s;
}

// The closed polygon through the corners (degree 1, clamped, its last point the first).
Curve polygon(std::vector<glm::dvec3> corners) {
    corners.push_back(corners.front());
    Curve c;
    c.degree = 1;
    c.points = corners;
    c.weights.assign(corners.size(), 1.0);
    c.knots = clamped_uniform_knots(static_cast<int>(corners.size()), 1);
    return c;
}

glm::dvec2 at(const Curve& c, double t) {
    return uv(*curve_point(c, t));
}

} // namespace

TEST(ProjectedLoop, CircleOnATiltedPlaneIsTheScaledCircleAndCutsItsArea) {
    const Surface s = tilted_plane(4, 2);
    const Curve circle = *full_circle({2, 1, 5}, 0.5, Plane::xy);
    auto loop = projected_loop(s, circle, {0, 0, -1});
    ASSERT_TRUE(loop) << loop.error().message;
    EXPECT_EQ(loop->curves.size(), 4u); // the circle's four quarter arcs meet at C0 knots
    // Every point of the loop is the circle's point scaled into the unit domain.
    for (const Curve& c : loop->curves) {
        const Interval d = domain(c);
        for (int k = 0; k <= 20; ++k) {
            const glm::dvec2 q = at(c, d.lo + (d.hi - d.lo) * k / 20.0);
            const double r = glm::length(glm::dvec2((q.x - 0.5) * 4, (q.y - 0.5) * 2));
            EXPECT_NEAR(r, 0.5, 1e-5);
        }
    }
    // Runs as the circle runs (counter-clockwise seen from +z); as a hole it cuts pi r^2 of
    // the plane, whose area element is sqrt(1 + 0.1^2) dx dy.
    Trim t;
    t.holes.push_back(reversed(*loop));
    ASSERT_TRUE(validate_trim(t, domain(s)));
    const double slope = std::sqrt(1.01);
    EXPECT_NEAR(trimmed_area(s, t), (8 - std::numbers::pi * 0.25) * slope, 1e-6);
}

TEST(ProjectedLoop, PointsOfACurvedSurfaceLieOnTheCurveSeenAlongTheDirection) {
    const Surface s = hill();
    const Curve circle = *full_circle({1.1, 0.9, 0}, 0.6, Plane::xy);
    auto loop = projected_loop(s, circle, {0, 0, 1}, 1e-7);
    ASSERT_TRUE(loop) << loop.error().message;
    for (const Curve& c : loop->curves) {
        const Interval d = domain(c);
        for (int k = 0; k <= 50; ++k) {
            const glm::dvec2 q = at(c, d.lo + (d.hi - d.lo) * k / 50.0);
            const glm::dvec3 p = *surface_point(s, q.x, q.y);
            EXPECT_NEAR(glm::length(glm::dvec2(p.x - 1.1, p.y - 0.9)), 0.6, 1e-5);
        }
    }
    Trim t;
    t.outer = *loop;
    EXPECT_TRUE(validate_trim(t, domain(s)));
}

TEST(ProjectedLoop, AlongYOntoAnUprightSurface) {
    // The plane y = 0.2 z standing over x in [0, 3], z in [0, 1]: a square drawn in xz.
    Surface s;
    s.degree_u = s.degree_v = 1;
    s.n_u = s.n_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, 0.2, 1}, {3, 0, 0}, {3, 0.2, 1}};
    s.weights = {1, 1, 1, 1};
    const Curve square = polygon({{1, -7, 0.25}, {2, -7, 0.25}, {2, -7, 0.75}, {1, -7, 0.75}});
    auto loop = projected_loop(s, square, {0, 1, 0});
    ASSERT_TRUE(loop) << loop.error().message;
    ASSERT_EQ(loop->curves.size(), 4u); // one piece per side: the corners stay corners
    const glm::dvec2 corners[] = {
        {1 / 3.0, 0.25}, {2 / 3.0, 0.25}, {2 / 3.0, 0.75}, {1 / 3.0, 0.75}};
    for (int k = 0; k < 4; ++k) {
        const glm::dvec2 start = at(loop->curves[k], domain(loop->curves[k]).lo);
        EXPECT_NEAR(start.x, corners[k].x, 1e-12);
        EXPECT_NEAR(start.y, corners[k].y, 1e-12);
        // Closed exactly: each piece ends where the next starts.
        EXPECT_EQ(loop->curves[k].points.back(), loop->curves[(k + 1) % 4].points.front());
    }
}

TEST(ProjectedLoop, ErrorsNameWhatIsWrong) {
    const Surface s = tilted_plane(4, 2);
    const Curve circle = *full_circle({2, 1, 0}, 0.5, Plane::xy);

    auto zero = projected_loop(s, circle, {0, 0, 0});
    ASSERT_FALSE(zero);
    EXPECT_EQ(zero.error().code, ErrorCode::schema);
    EXPECT_EQ(zero.error().path, "/direction");

    Curve open = polygon({{1, 1, 0}, {2, 1, 0}, {2, 1.5, 0}});
    open.points.back() = {1, 1.25, 0};
    auto gap = projected_loop(s, open, {0, 0, 1});
    ASSERT_FALSE(gap);
    EXPECT_EQ(gap.error().code, ErrorCode::geometry);
    EXPECT_NE(gap.error().message.find("not closed"), std::string::npos) << gap.error().message;
    EXPECT_NE(gap.error().message.find("0.25 apart"), std::string::npos) << gap.error().message;

    // Half of this circle lies beyond the plane's edge x = 4.
    const Curve outside = *full_circle({4, 1, 0}, 0.5, Plane::xy);
    auto missed = projected_loop(s, outside, {0, 0, 1});
    ASSERT_FALSE(missed);
    EXPECT_EQ(missed.error().code, ErrorCode::geometry);
    EXPECT_EQ(missed.error().path, "/curve");
    EXPECT_NE(missed.error().message.find("does not project onto the surface"), std::string::npos)
        << missed.error().message;

    // Seen along y the plane is an edge (the segment z = 0.1 x): lines through the circle's
    // points (z = 0, x > 1) never meet it.
    auto edge_on = projected_loop(s, circle, {0, 1, 0});
    EXPECT_FALSE(edge_on);
}
