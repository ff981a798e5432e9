// Point and leg picking on a 2D canvas (see polygon_hits.hpp).
#include "ui/view/polygon_hits.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

namespace isoparm::ui {

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double s = len2 > 0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + s * ab));
}

std::optional<int> point_under(std::span<const glm::dvec2> points, const glm::dvec2& mouse,
                               double radius) {
    std::optional<int> hit;
    double best = radius;
    for (int i = static_cast<int>(points.size()) - 1; i >= 0; --i) {
        const double d = glm::length(points[static_cast<std::size_t>(i)] - mouse);
        if (d < best || (d == best && !hit)) {
            best = d;
            hit = i;
        }
    }
    return hit;
}

std::optional<LegHit> leg_under(std::span<const glm::dvec2> points, const glm::dvec2& mouse,
                                double radius) {
    int leg = -1;
    double best = radius;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const double d = distance_to_segment(mouse, points[i], points[i + 1]);
        if (d <= best) best = d, leg = static_cast<int>(i);
    }
    if (leg < 0) return std::nullopt;
    const glm::dvec2 a = points[static_cast<std::size_t>(leg)];
    const glm::dvec2 b = points[static_cast<std::size_t>(leg) + 1];
    const double len = glm::length(b - a);
    const double s = len > 0 ? std::clamp(glm::dot(mouse - a, b - a) / (len * len), 0., 1.) : 0;
    return LegHit{leg, s};
}

} // namespace isoparm::ui
