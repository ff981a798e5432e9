// The domain triangle's picture of a rational patch's denominator: where it is negative and
// its zero set, recomputed only for new weights.
#include <gtest/gtest.h>

#include <cmath>

#include "core/doc/commands_triangle.hpp"
#include "ui/view/triangle_denominator.hpp"

using namespace isoparm;
using namespace isoparm::ui;

namespace {

geom::TrianglePatch cubic_with_centre_weight(double w) {
    geom::TrianglePatch t = doc::make_flat_triangle(3, true).value();
    t.weights[static_cast<std::size_t>(geom::TrianglePatch::index(3, 1, 1))] = w;
    return t;
}

} // namespace

TEST(TriangleDenominator, PositiveWeightsHaveNoZeroSet) {
    const TriangleDenominatorView v = triangle_denominator_view(cubic_with_centre_weight(2), 24);
    EXPECT_TRUE(v.negative.empty());
    EXPECT_TRUE(v.zero_set.empty());
}

TEST(TriangleDenominator, ACentreWeightOfMinusEightMakesAClosedCurve) {
    // D = 1 - 9 B_111: 1 on the border, -1 at the centre, zero where B_111 = 1 / 9.
    const geom::TrianglePatch t = cubic_with_centre_weight(-8);
    // 25 subdivisions: with 24, rst = 1 / 54 at the grid point (4, 4, 16) / 24, where D is
    // zero and the curve passes through a vertex of six small triangles (still drawn right, as
    // six zero-length segments, but not a chain of segments to check).
    const TriangleDenominatorView v = triangle_denominator_view(t, 25);
    ASSERT_FALSE(v.negative.empty());
    ASSERT_GT(v.zero_set.size(), 12u);
    for (const auto& small : v.negative)
        for (const geom::Barycentric& p : small)
            EXPECT_GT(std::min({p[0], p[1], p[2]}), 0) << "border";
    // The zero set's points lie on D = 0 up to the linear interpolation's error (h^2 = 1/625
    // times D's second derivatives, about 20 here).
    for (const auto& segment : v.zero_set)
        for (const geom::Barycentric& p : segment) {
            EXPECT_NEAR(geom::triangle_denominator(t, p), 0, 0.05);
            EXPECT_NEAR(p[0] + p[1] + p[2], 1, 1e-12);
        }
    // A closed curve: every segment end is the end of exactly one other segment.
    for (std::size_t a = 0; a < v.zero_set.size(); ++a)
        for (const geom::Barycentric& p : v.zero_set[a]) {
            int shared = 0;
            for (std::size_t b = 0; b < v.zero_set.size(); ++b)
                for (const geom::Barycentric& q : v.zero_set[b])
                    if (b != a && std::abs(p[0] - q[0]) + std::abs(p[1] - q[1]) < 1e-12) ++shared;
            EXPECT_EQ(shared, 1);
        }
}

TEST(TriangleDenominator, TheKeyIsTheDegreeAndTheWeights) {
    geom::TrianglePatch t = cubic_with_centre_weight(-8);
    const TriangleDenominatorView v = triangle_denominator_view(t, 24);
    EXPECT_TRUE(same_denominator(v, t, 24));
    EXPECT_FALSE(same_denominator(v, t, 32));
    t.points[0].x += 1; // a moved point keeps the picture
    EXPECT_TRUE(same_denominator(v, t, 24));
    t.weights[0] = 3;
    EXPECT_FALSE(same_denominator(v, t, 24));
    EXPECT_FALSE(same_denominator(TriangleDenominatorView{}, t, 24));
}
