// Closed curves meet C^(p-1) at the seam; knot splitting keeps the points and moves one copy.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/reshape.hpp"
#include "core/geom/validate.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;
using isoparm::testing::RandomGeometry;

namespace {

TEST(ClosePeriodic, EndsMeetWithContinuityOneBelowTheDegree) {
    RandomGeometry g(21);
    for (int p = 1; p <= 5; ++p) {
        for (bool rational : {false, true}) {
            Curve c = g.curve(p, p + 4, rational);
            if (rational)
                for (double& w : c.weights) w = g.uniform(0.5, 2);
            const Curve closed = close_periodic(c);
            ASSERT_TRUE(validate_curve(closed).ok()) << validate_curve(closed).error().message;
            const Interval d = domain(closed.knots, p, closed.count());
            EXPECT_EQ(d.lo, 0.0);
            EXPECT_EQ(d.hi, 1.0);
            const auto start = *curve_derivatives(closed, d.lo, std::min(p - 1, 3));
            const auto end = *curve_derivatives(closed, d.hi, std::min(p - 1, 3));
            for (int k = 0; k <= std::min(p - 1, 3); ++k) {
                const double scale = std::max(1.0, glm::length(start[k]));
                EXPECT_LT(glm::length(start[k] - end[k]), 1e-11 * scale) << p << " C^" << k;
            }
        }
    }
}

TEST(ClosePeriodic, ASurfaceClosesEveryLineOfTheDirection) {
    RandomGeometry g(22);
    const Surface s = g.surface(2, 3, 4, 5, false);
    const Surface closed = close_periodic(s, Dir::v);
    ASSERT_TRUE(validate_surface(closed).ok());
    EXPECT_EQ(closed.n_v, 5 + 3);
    EXPECT_EQ(closed.n_u, 4);
    const double u = 0.37 * s.knots_u[2] + 0.63 * s.knots_u[4];
    EXPECT_LT(glm::length(*surface_point(closed, u, 0) - *surface_point(closed, u, 1)), 1e-12);
}

TEST(SplitKnot, MovesOneCopyAndReportsTheChange) {
    Curve c;
    c.degree = 3;
    c.knots = {0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1};
    c.points = {{0, 0, 0}, {1, 2, 0}, {2, 0, 0}, {3, 2, 0}, {4, 0, 0}, {5, 1, 0}};
    c.weights.assign(6, 1.0);
    auto split = split_knot(c, 0.5, std::nullopt);
    ASSERT_TRUE(split.ok()) << split.error().message;
    EXPECT_EQ(split->result.knots, (Knots{0, 0, 0, 0, 0.495, 0.5, 1, 1, 1, 1}));
    EXPECT_EQ(split->result.points, c.points);
    EXPECT_GT(split->max_change, 0);
    EXPECT_LT(split->max_change, 0.1);
    // A larger delta moves the shape more.
    auto wider = split_knot(c, 0.5, 0.2);
    ASSERT_TRUE(wider.ok());
    EXPECT_GT(wider->max_change, split->max_change);

    EXPECT_EQ(split_knot(c, 0.25, std::nullopt).error().path, "/knot"); // not a knot
    EXPECT_EQ(split_knot(c, 0, std::nullopt).error().path, "/knot");    // nothing before it
    EXPECT_EQ(split_knot(c, 0.5, 0.5).error().path, "/delta");          // reaches knot 0
    EXPECT_EQ(split_knot(c, 0.5, -1.0).error().path, "/delta");
}

} // namespace
