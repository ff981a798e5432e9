// Picking control points in the 3D view: the nearest projected point within a pixel radius.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "ui/view/camera.hpp"

namespace isoparm::ui {

// The index of the visible point nearest to `mouse` within `radius_px`; on a tie in screen
// distance the one nearer the eye wins. nullopt when none is close enough.
std::optional<std::size_t> pick_nearest(const std::vector<Projected>& points,
                                        const glm::dvec2& mouse, double radius_px);

// A control point of an object, as the 3D view and the control-point panel address it.
struct PointRef {
    std::uint64_t object = 0;
    int i = -1, j = -1;
};

} // namespace isoparm::ui
