// Picking on the curve designer's canvas: the nearest point (then the one on top), legs by
// distance, where along.
#include <gtest/gtest.h>

#include <vector>

#include "ui/view/polygon_hits.hpp"

namespace isoparm::ui {
namespace {

TEST(PolygonHits, DistanceToASegmentAndToADegenerateOne) {
    EXPECT_DOUBLE_EQ(distance_to_segment({5, 3}, {0, 0}, {10, 0}), 3.0);
    EXPECT_DOUBLE_EQ(distance_to_segment({-4, 3}, {0, 0}, {10, 0}), 5.0); // past the end
    EXPECT_DOUBLE_EQ(distance_to_segment({3, 4}, {0, 0}, {0, 0}), 5.0);
}

TEST(PolygonHits, TheNearestPointThenTheOneDrawnLast) {
    const std::vector<glm::dvec2> pts{{0, 0}, {4, 0}, {100, 0}};
    EXPECT_EQ(point_under(pts, {2, 0}, 8.0), 1);   // both equally near: the later one (on top)
    EXPECT_EQ(point_under(pts, {0, 0}, 8.0), 0);   // on P0's centre under P1's disk: P0
    EXPECT_EQ(point_under(pts, {1.9, 0}, 8.0), 0); // nearer to P0
    EXPECT_EQ(point_under(pts, {-8, 0}, 8.0), 0);  // the radius counts
    EXPECT_FALSE(point_under(pts, {50, 0}, 8.0).has_value());
    EXPECT_FALSE(point_under({}, {0, 0}, 8.0).has_value());
}

TEST(PolygonHits, TheNearestLegAndWhereAlongIt) {
    const std::vector<glm::dvec2> pts{{0, 0}, {10, 0}, {10, 10}};
    const auto hit = leg_under(pts, {2.5, 1}, 8.0);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->leg, 0);
    EXPECT_DOUBLE_EQ(hit->s, 0.25);
    const auto second = leg_under(pts, {11, 6}, 8.0);
    ASSERT_TRUE(second.has_value());
    EXPECT_EQ(second->leg, 1);
    EXPECT_DOUBLE_EQ(second->s, 0.6);
    // At the shared corner both legs are as near: the later one.
    EXPECT_EQ(leg_under(pts, {10, 0}, 8.0)->leg, 1);
    EXPECT_FALSE(leg_under(pts, {30, 30}, 8.0).has_value());
    EXPECT_FALSE(leg_under(std::vector<glm::dvec2>{{0, 0}}, {0, 0}, 8.0).has_value());
}

} // namespace
} // namespace isoparm::ui
