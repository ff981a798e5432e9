// Domain square and plane mappings, knot ticks.
#include <gtest/gtest.h>

#include "ui/view/canvas_map.hpp"

using namespace isoparm;
using namespace isoparm::ui;

TEST(DomainSquare, MapsCornersWithVUpward) {
    const Rect sq{10, 20, 200, 100};
    EXPECT_EQ(domain_to_pixel(sq, {0, 0}), glm::dvec2(10, 120)); // bottom-left
    EXPECT_EQ(domain_to_pixel(sq, {1, 1}), glm::dvec2(210, 20)); // top-right
    EXPECT_EQ(domain_to_pixel(sq, {0.25, 0.5}), glm::dvec2(60, 70));
}

TEST(DomainSquare, InverseRoundTripsAndClamps) {
    const Rect sq{10, 20, 200, 100};
    for (double u : {0.0, 0.3, 0.75, 1.0})
        for (double v : {0.0, 0.6, 1.0}) {
            const glm::dvec2 back = pixel_to_domain(sq, domain_to_pixel(sq, {u, v}));
            EXPECT_NEAR(back.x, u, 1e-12);
            EXPECT_NEAR(back.y, v, 1e-12);
        }
    EXPECT_EQ(pixel_to_domain(sq, {-50, 500}), glm::dvec2(0, 0));
    EXPECT_EQ(pixel_to_domain(sq, {500, -50}), glm::dvec2(1, 1));
}

TEST(DomainSquare, ParametersNormaliseOverTheDomainExactlyAtTheEnds) {
    const geom::Interval d{0.2, 1.7};
    EXPECT_DOUBLE_EQ(normalize_param(d, 0.2), 0);
    EXPECT_DOUBLE_EQ(normalize_param(d, 1.7), 1);
    EXPECT_NEAR(normalize_param(d, 0.95), 0.5, 1e-15);
    EXPECT_EQ(denormalize_param(d, 1.0), 1.7); // bit-exact end of the domain
    EXPECT_EQ(denormalize_param(d, 0.0), 0.2);
    EXPECT_NEAR(denormalize_param(d, 0.5), 0.95, 1e-15);
}

TEST(KnotTicks, DistinctKnotsWithExactMultiplicities) {
    // The paper's 0^4 0.5 0.75 1^4 plus a double knot.
    const geom::Knots U{0, 0, 0, 0, 0.5, 0.5, 0.75, 1, 1, 1, 1};
    const auto t = knot_ticks(U, 3, 7);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[0].value, 0);
    EXPECT_EQ(t[0].multiplicity, 4);
    EXPECT_FALSE(t[0].interior);
    EXPECT_EQ(t[1].value, 0.5);
    EXPECT_EQ(t[1].multiplicity, 2);
    EXPECT_EQ(t[1].first_index, 4);
    EXPECT_TRUE(t[1].interior);
    EXPECT_DOUBLE_EQ(t[2].position, 0.75);
    EXPECT_EQ(t[3].multiplicity, 4);
}

TEST(KnotTicks, NearlyEqualKnotsStayDistinct) {
    const geom::Knots U{0, 0, 0.5, 0.5 + 1e-12, 1, 1};
    const auto t = knot_ticks(U, 1, 4);
    ASSERT_EQ(t.size(), 4u);
    EXPECT_EQ(t[1].multiplicity, 1);
    EXPECT_EQ(t[2].multiplicity, 1);
}

TEST(KnotTicks, UnclampedVectorsShowOnlyTheDomain) {
    const geom::Knots U{0, 1, 2, 3, 4, 5, 6, 7}; // p = 3, n = 4: domain [3, 4]
    const auto t = knot_ticks(U, 3, 4);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0].value, 3);
    EXPECT_EQ(t[1].value, 4);
}

TEST(HitTick, NearestWithinRadius) {
    const std::vector<double> px{10, 50, 53, 100};
    EXPECT_EQ(hit_tick(px, 52, 5), 2u);
    EXPECT_EQ(hit_tick(px, 49, 5), 1u);
    EXPECT_FALSE(hit_tick(px, 75, 5).has_value());
}

TEST(HitTick, KnotHandlesAreGenerousAndIgnoreTheFixedEnds) {
    // At scale 1 the handle reaches 9 px either side of the tick: an 18 px target.
    EXPECT_GE(2 * knot_handle_radius(1), 12.0);
    // Presentation mode (scale 1.5) makes it larger still.
    EXPECT_GT(knot_handle_radius(1.5f), knot_handle_radius(1));
    const std::vector<double> px{10, 16, 60, 100};
    const std::vector<bool> movable{false, true, true, false};
    const double r = knot_handle_radius(1);
    // 8 px off an interior tick still catches it.
    EXPECT_EQ(hit_movable_tick(px, movable, 68, r), 2u);
    // Right on the fixed end, the interior knot 6 px away is the one caught.
    EXPECT_EQ(hit_movable_tick(px, movable, 10, r), 1u);
    EXPECT_FALSE(hit_movable_tick(px, movable, 100, r).has_value());
    EXPECT_FALSE(hit_movable_tick(px, movable, 80, r).has_value());
}

TEST(ThinLabels, KeepsEndsAndDropsCrowdedOnes) {
    const auto keep = thin_labels({0, 5, 30, 33, 60, 100}, 20);
    EXPECT_EQ(keep, (std::vector<bool>{true, false, true, false, true, true}));
    // The last end wins over a kept label too close to it.
    EXPECT_EQ(thin_labels({0, 50, 95, 100}, 20), (std::vector<bool>{true, true, false, true}));
    EXPECT_EQ(thin_labels({7}, 20), (std::vector<bool>{true}));
    EXPECT_TRUE(thin_labels({}, 20).empty());
}

TEST(PlaneMap, FitsTheBoxAtEqualScaleAndRoundTrips) {
    const Rect canvas{0, 0, 200, 100};
    const PlaneMap m = fit_plane(canvas, {-1, -1}, {3, 1}, 10);
    // Height decides: 2 units over 80 px is coarser than 4 units over 180 px.
    EXPECT_NEAR(m.units_per_px, 2.0 / 80.0, 1e-12);
    const glm::dvec2 c = plane_to_pixel(m, {1, 0});
    EXPECT_NEAR(c.x, 100, 1e-9);
    EXPECT_NEAR(c.y, 50, 1e-9);
    // Up in the world is up on screen.
    EXPECT_LT(plane_to_pixel(m, {1, 1}).y, c.y);
    const glm::dvec2 back = pixel_to_plane(m, plane_to_pixel(m, {2.5, -0.75}));
    EXPECT_NEAR(back.x, 2.5, 1e-12);
    EXPECT_NEAR(back.y, -0.75, 1e-12);
    // The box's corners are inside the canvas.
    for (glm::dvec2 p : {glm::dvec2(-1, -1), glm::dvec2(3, 1)}) {
        const glm::dvec2 q = plane_to_pixel(m, p);
        EXPECT_GE(q.x, 0);
        EXPECT_LE(q.x, 200);
        EXPECT_GE(q.y, 0);
        EXPECT_LE(q.y, 100);
    }
}
