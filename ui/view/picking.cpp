// Picking: nearest projected point within a radius, ties broken by depth.
#include "ui/view/picking.hpp"

#include <glm/geometric.hpp>

namespace isoparm::ui {

std::optional<std::size_t> pick_nearest(const std::vector<Projected>& points,
                                        const glm::dvec2& mouse, double radius_px) {
    std::optional<std::size_t> best;
    double best_dist = 0, best_depth = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Projected& p = points[k];
        if (!p.visible) continue;
        const double dist = glm::length(p.pixel - mouse);
        if (dist > radius_px) continue;
        // Within half a pixel of the best counts as a tie: the point nearer the eye wins.
        const bool closer = dist < best_dist - 0.5;
        const bool tie_in_front = dist <= best_dist + 0.5 && p.depth < best_depth;
        if (!best || closer || tie_in_front) {
            best = k;
            best_dist = dist;
            best_depth = p.depth;
        }
    }
    return best;
}

} // namespace isoparm::ui
