// The triangular patch's panels without a window: the domain triangle on screen, typing a
// coordinate, names and steps of de Casteljau's construction, the heat map and its peak.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

#include "core/geom/triangle.hpp"
#include "ui/view/triangle_domain.hpp"

using namespace isoparm;
using namespace isoparm::ui;
using geom::Barycentric;
using geom::TrianglePatch;

namespace {

// A cubic patch over the unit triangle, lifted in the middle; `heavy` puts weight 2 on b_111.
TrianglePatch cubic(bool heavy) {
    TrianglePatch t;
    t.degree = 3;
    t.rational = heavy;
    for (int i = 3; i >= 0; --i)
        for (int j = 3 - i; j >= 0; --j) {
            t.points.push_back({i / 3.0, j / 3.0, i == 1 && j == 1 ? 1.0 : 0.0});
            t.weights.push_back(heavy && i == 1 && j == 1 ? 2.0 : 1.0);
        }
    return t;
}

void expect_near(const Barycentric& a, const Barycentric& b, double tol) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tol) << "coordinate " << k;
}

TEST(TriangleCanvas, EquilateralWithRRightSUpTLeft) {
    const TriangleCanvas c = fit_triangle({0, 0, 400, 300}, 10);
    const double side = c.vertex[0].x - c.vertex[2].x;
    EXPECT_GT(side, 0);
    EXPECT_EQ(c.vertex[0].y, c.vertex[2].y); // r = 1 and t = 1 on the base
    EXPECT_LT(c.vertex[1].y, c.vertex[0].y); // s = 1 above it
    EXPECT_NEAR(c.vertex[0].y - c.vertex[1].y, side * std::sqrt(3.0) / 2, 1e-9);
    EXPECT_NEAR(c.vertex[1].x, (c.vertex[0].x + c.vertex[2].x) / 2, 1e-9);
    EXPECT_NEAR(c.vertex[0].y - c.vertex[1].y, 280, 1e-9); // height-limited: 300 - 2 * 10
    EXPECT_NEAR((c.vertex[0].x + c.vertex[2].x) / 2, 200, 1e-9);
}

TEST(TriangleCanvas, PixelsRoundTripAndVerticesAreTheUnitPoints) {
    const TriangleCanvas c = fit_triangle({20, 30, 300, 300}, 8);
    EXPECT_EQ(barycentric_to_pixel(c, {1, 0, 0}), c.vertex[0]);
    EXPECT_EQ(barycentric_to_pixel(c, {0, 1, 0}), c.vertex[1]);
    EXPECT_EQ(barycentric_to_pixel(c, {0, 0, 1}), c.vertex[2]);
    for (const Barycentric& p :
         {Barycentric{0.2, 0.3, 0.5}, Barycentric{0.6, 0.1, 0.3}, Barycentric{1.2, -0.1, -0.1}})
        expect_near(pixel_to_barycentric(c, barycentric_to_pixel(c, p)), p, 1e-12);
}

TEST(TriangleCanvas, ADotIsFoundWithinItsRadiusOnly) {
    const TriangleCanvas c = fit_triangle({0, 0, 400, 300}, 10);
    const glm::dvec2 b111 = barycentric_to_pixel(c, {1.0 / 3, 1.0 / 3, 1.0 / 3});
    EXPECT_EQ(domain_point_at(c, 3, b111 + glm::dvec2(3, -2), 6), std::pair(1, 1));
    EXPECT_EQ(domain_point_at(c, 3, b111 + glm::dvec2(8, 0), 6), std::nullopt);
    EXPECT_EQ(domain_point_at(c, 3, c.vertex[1], 6), std::pair(0, 3)); // b030 at s = 1
    EXPECT_EQ(domain_point_at(c, 3, c.vertex[2] + glm::dvec2(-4, 3), 6), std::pair(0, 0));
    // Between two dots closer than twice the radius: the nearer one.
    const glm::dvec2 b300 = c.vertex[0], b210 = barycentric_to_pixel(c, {2.0 / 3, 1.0 / 3, 0});
    EXPECT_EQ(domain_point_at(c, 3, b300 + 0.4 * (b210 - b300), 1000), std::pair(3, 0));
    EXPECT_EQ(domain_point_at(c, 3, b300 + 0.6 * (b210 - b300), 1000), std::pair(2, 1));
}

TEST(TriangleCanvas, ClampingIsTheNearestPointOfTheTriangle) {
    const Barycentric inside = {0.2, 0.3, 0.5};
    EXPECT_EQ(clamp_to_triangle(inside), inside); // bit for bit
    // Beyond the edge t = 0, perpendicularly: back to the foot on that edge.
    expect_near(clamp_to_triangle({0.6, 0.6, -0.2}), {0.5, 0.5, 0}, 1e-15);
    // Far past the vertex r = 1: the vertex itself.
    expect_near(clamp_to_triangle({3, -1, -1}), {1, 0, 0}, 1e-15);
    // Past an edge but off the perpendicular: the nearest point on the edge r = 0.
    expect_near(clamp_to_triangle({-0.2, 0.9, 0.3}), {0, 0.8, 0.2}, 1e-15);
    // In pixels too: no point of the triangle is nearer to the pixel than its clamp.
    const TriangleCanvas c = fit_triangle({0, 0, 200, 200}, 0);
    const glm::dvec2 outside{250, -40};
    const glm::dvec2 foot =
        barycentric_to_pixel(c, clamp_to_triangle(pixel_to_barycentric(c, outside)));
    for (int a = 0; a <= 20; ++a)
        for (int b = 0; a + b <= 20; ++b) {
            const glm::dvec2 q = barycentric_to_pixel(c, {a / 20.0, b / 20.0, (20 - a - b) / 20.0});
            EXPECT_LE(glm::length(outside - foot), glm::length(outside - q) + 1e-9);
        }
}

TEST(TriangleTyping, OneCoordinateTypedTheOthersKeepTheirRatio) {
    const auto q = set_barycentric_coordinate({0.2, 0.3, 0.5}, 0, 0.6);
    ASSERT_TRUE(q);
    expect_near(*q, {0.6, 0.15, 0.25}, 1e-15); // s : t stays 3 : 5
    EXPECT_NEAR((*q)[0] + (*q)[1] + (*q)[2], 1.0, 1e-15);
    // From a vertex the other two had nothing: they share what is left.
    const auto v = set_barycentric_coordinate({0, 0, 1}, 2, 0.4);
    ASSERT_TRUE(v);
    expect_near(*v, {0.3, 0.3, 0.4}, 1e-15);
    // t = 1 is a vertex.
    expect_near(*set_barycentric_coordinate({0.2, 0.3, 0.5}, 2, 1), {0, 0, 1}, 0);
}

TEST(TriangleTyping, ValuesOutsideTheTriangleAreRefusedWithTheReason) {
    for (double bad : {-0.1, 1.5, std::nan(""), std::numeric_limits<double>::infinity()}) {
        const auto q = set_barycentric_coordinate({0.2, 0.3, 0.5}, 1, bad);
        ASSERT_FALSE(q) << bad;
        EXPECT_NE(q.error().message.find("s = "), std::string::npos) << q.error().message;
        EXPECT_NE(q.error().message.find("outside the triangle"), std::string::npos);
    }
}

TEST(TriangleSteps, NamesTextsAndLevelSizes) {
    EXPECT_EQ(triangle_point_name(3, 0, 2, 1), "b210");
    EXPECT_EQ(triangle_point_name(3, 1, 2, 0), "b^1_200");
    EXPECT_EQ(triangle_point_name(3, 3, 0, 0), "b^3_000");
    EXPECT_EQ(triangle_point_name(12, 0, 2, 10), "b2,10,0");
    EXPECT_EQ(triangle_level_size(3, 0), 10);
    EXPECT_EQ(triangle_level_size(3, 1), 6);
    EXPECT_EQ(triangle_level_size(3, 3), 1);
    EXPECT_EQ(triangle_step_text(0, 3), "the 10 control points b_ijk");
    EXPECT_EQ(triangle_step_text(2, 3), "level 2, the 3 points b^2_ijk with i + j + k = 1");
    EXPECT_NE(triangle_step_text(3, 3).find("S(r, s, t)"), std::string::npos);
    EXPECT_EQ(triangle_step_text(-1, 3), "all levels");
}

TEST(TriangleSteps, LevelWeightsEndInTheDenominator) {
    const TrianglePatch t = cubic(true);
    const Barycentric p = {0.2, 0.3, 0.5};
    const auto w = triangle_level_weights(t, p);
    ASSERT_EQ(w.size(), 4u);
    EXPECT_EQ(w[0], t.weights);
    EXPECT_EQ(w[1].size(), 6u);
    ASSERT_EQ(w[3].size(), 1u);
    // The last level is sum w_ijk B^3_ijk.
    double denominator = 0;
    for (int i = 3; i >= 0; --i)
        for (int j = 3 - i; j >= 0; --j)
            denominator +=
                t.weights[TrianglePatch::index(3, i, j)] * geom::bernstein_triangle(3, i, j, p);
    EXPECT_NEAR(w[3][0], denominator, 1e-15);
    EXPECT_GT(w[3][0], 1.0); // the heavy b_111 pulls
}

TEST(TriangleHeatMap, ValuesAtTheGridPointsAndTheCacheKey) {
    const TrianglePatch t = cubic(false);
    const TriangleHeat h = triangle_heat(t, 1, 1, 6);
    ASSERT_EQ(h.values.size(), 28u);
    // Grid point (2, 2, 2) / 6 = the centre, where B^3_111 = 6 / 27.
    EXPECT_NEAR(h.values[TrianglePatch::index(6, 2, 2)], 6.0 / 27, 1e-15);
    EXPECT_EQ(h.values[TrianglePatch::index(6, 6, 0)], 0.0); // b_111 is 0 at a vertex
    EXPECT_NEAR(h.largest, 6.0 / 27, 1e-15);
    EXPECT_TRUE(same_heat(h, t, 1, 1, 6));
    EXPECT_FALSE(same_heat(h, t, 2, 1, 6));
    TrianglePatch moved = t;
    moved.points[3].z += 0.1;
    EXPECT_TRUE(same_heat(h, moved, 1, 1, 6)); // the basis does not depend on the points...
    moved.weights[3] = 2;
    EXPECT_FALSE(same_heat(h, moved, 1, 1, 6)); // ...but on the weights
    EXPECT_FALSE(same_heat(h, cubic(true), 1, 1, 6));
}

TEST(TriangleHeatMap, PolynomialPeakAtItsDomainPointRationalPeakFound) {
    const TrianglePatch plain = cubic(false);
    const BasisPeak b = triangle_basis_peak(plain, 2, 0, triangle_heat(plain, 2, 0, 12));
    EXPECT_TRUE(b.exact);
    expect_near(b.at, {2.0 / 3, 0, 1.0 / 3}, 1e-15);
    EXPECT_NEAR(b.value, 4.0 / 9, 1e-15); // 3 (2/3)^2 (1/3)

    // Weight 2 on b_111 raises R_111 above B_111's 6/27 at the centre, where by symmetry it
    // peaks: R = 2 B / (1 + B) there.
    const TrianglePatch heavy = cubic(true);
    const BasisPeak r = triangle_basis_peak(heavy, 1, 1, triangle_heat(heavy, 1, 1, 10));
    EXPECT_FALSE(r.exact);
    ASSERT_TRUE(r.found);
    const double B = 6.0 / 27;
    EXPECT_NEAR(r.value, 2 * B / (1 + B), 1e-12);
    expect_near(r.at, {1.0 / 3, 1.0 / 3, 1.0 / 3}, 1e-5);
    // No grid point and no search step beats it.
    const TriangleHeat fine = triangle_heat(heavy, 1, 1, 60);
    EXPECT_LE(fine.largest, r.value + 1e-15);
}

TEST(TriangleHeatMap, ANegativeWeightsLowestValueIsSearched) {
    // w_111 = -0.5: R_111 = -0.5 B / (1 - 1.5 B) is negative inside, lowest at the centre by
    // symmetry (B_111 is largest there and the denominator smallest).
    TrianglePatch t = cubic(true);
    t.weights[TrianglePatch::index(3, 1, 1)] = -0.5;
    const TriangleHeat h = triangle_heat(t, 1, 1, 10);
    const BasisPeak low = triangle_basis_peak(t, 1, 1, h, true);
    ASSERT_TRUE(low.found);
    EXPECT_FALSE(low.exact);
    const double B = 6.0 / 27;
    EXPECT_NEAR(low.value, -0.5 * B / (1 - 1.5 * B), 1e-12);
    expect_near(low.at, {1.0 / 3, 1.0 / 3, 1.0 / 3}, 1e-5);
    // Its largest value is 0, on the border, where B_111 vanishes.
    const BasisPeak high = triangle_basis_peak(t, 1, 1, h);
    EXPECT_EQ(high.value, 0.0);
    EXPECT_LT(std::min({high.at[0], high.at[1], high.at[2]}), 1e-12);
    EXPECT_FALSE(h.denominator_vanishes); // 1 - 1.5 B >= 1 - 1.5 * 6 / 27 > 0
}

TEST(TriangleHeatMap, NoExtremeWhereTheDenominatorVanishesInside) {
    // w_111 = -8: the denominator 1 - 9 B_111 is 1 on the border and 1 - 9 * 6 / 27 = -1 at
    // the centre, zero on a closed curve between: R_111 = -8 B / (1 - 9 B) has a pole there,
    // and no largest or smallest value.
    TrianglePatch t = cubic(true);
    t.weights[TrianglePatch::index(3, 1, 1)] = -8;
    const TriangleHeat h = triangle_heat(t, 1, 1, 10);
    EXPECT_TRUE(h.denominator_vanishes);
    for (bool lowest : {false, true}) {
        const BasisPeak e = triangle_basis_peak(t, 1, 1, h, lowest);
        EXPECT_TRUE(e.unbounded);
        EXPECT_FALSE(e.found);
    }
    // The denominator itself: 1 - 9 B_111.
    EXPECT_NEAR(triangle_denominator(t, {1.0 / 3, 1.0 / 3, 1.0 / 3}), -1, 1e-14);
    EXPECT_EQ(triangle_denominator(t, {1, 0, 0}), 1);
}

} // namespace
