#include "ui/view/implicit_screen_level.hpp"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace isoparm::ui {

ScreenScale screen_scale(const Camera& camera, int height_px) {
    ScreenScale s;
    s.eye = camera_eye(camera);
    const double t = std::tan(camera.fov_y / 2);
    if (height_px > 0 && t > 0) s.pixels_at_unit_distance = height_px / (2 * t);
    return s;
}

int screen_level(const glm::dvec3& lo, const glm::dvec3& hi, double cell, const ScreenScale& s) {
    const double distance = glm::distance(s.eye, glm::clamp(s.eye, lo, hi));
    if (!(distance > 0) || !(cell > 0) || !(s.pixels_at_unit_distance > 0)) return 0;
    const double cell_pixels = cell * s.pixels_at_unit_distance / distance;
    int level = 0;
    while (level < max_screen_level && 2 * cell_pixels * (1 << level) <= screen_cell_pixels)
        ++level;
    return level;
}

} // namespace isoparm::ui
