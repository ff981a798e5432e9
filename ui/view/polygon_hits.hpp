// Picking on a 2D canvas without a window: which control point or polygon leg a press lands
// on (the curve designer's canvas, in pixels).
#pragma once

#include <optional>
#include <span>

#include <glm/vec2.hpp>

namespace isoparm::ui {

// The distance from p to the segment [a, b] (to a itself when a = b).
double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b);

// The point nearest to `mouse` within `radius`: a click on a point's centre takes that point
// even where a neighbour's disk overlaps it (a profile's crowded top on a projector's small
// canvas); of points equally near, the one drawn last (on top) wins.
std::optional<int> point_under(std::span<const glm::dvec2> points, const glm::dvec2& mouse,
                               double radius);

// The polygon leg (points[leg], points[leg + 1]) nearest to `mouse` within `radius` (on a
// tie the later leg), and where along it the mouse falls: s in [0, 1] from points[leg].
struct LegHit {
    int leg = 0;
    double s = 0;
};
std::optional<LegHit> leg_under(std::span<const glm::dvec2> points, const glm::dvec2& mouse,
                                double radius);

} // namespace isoparm::ui
