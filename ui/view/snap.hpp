// Grid and snap (pure): the grid step a canvas shows at its zoom, and where a dragged point
// lands: on another point, on an axis, or on a grid value, exactly (0.3 is the double that
// "0.3" reads as, not 3 * 0.1 = 0.30000000000000004).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace isoparm::ui {

// A grid step mantissa * 10^exponent with mantissa 1, 2 or 5 (the steps a ruler uses).
struct GridStep {
    int mantissa = 1;
    int exponent = 0;
    double value() const;
    bool operator==(const GridStep&) const = default;
};
// The smallest step whose lines are at least `min_pixels` apart at `pixels_per_unit` (a
// canvas's zoom): the grid thins out as the view zooms out and never turns into a grey wash.
GridStep grid_step_for(double pixels_per_unit, double min_pixels);
// The next coarser step (1 -> 2 -> 5 -> 10): the grid's major lines.
GridStep coarser(GridStep s);
// Grid value k: k * mantissa * 10^exponent, computed as one correctly rounded operation on
// exact integers ((k m) / 10^-e for a negative exponent), so it is the double nearest the
// decimal number: grid_value({1, -1}, 3) == 0.3.
double grid_value(GridStep s, long long k);
// The grid value nearest to x (halves away from zero).
double snap_to_grid(double x, GridStep s);
// How a grid value is written on a ruler: "0.3", "-2", "1e-05" (the shortest decimal).
std::string grid_label(GridStep s, long long k);
// The indices of the grid values inside [lo, hi], first and last (first > last when none).
struct GridRange {
    long long first = 0, last = -1;
};
GridRange grid_range(GridStep s, double lo, double hi);

// What a dragged point snaps to, switched on one by one (the Snap menu); a modifier key held
// during the drag (Alt) turns snapping off for that drag.
struct SnapSettings {
    bool grid = true;   // each coordinate to the nearest grid value
    bool axes = true;   // a coordinate near 0 to 0 (within radius_px), also with the grid off
    bool points = true; // to another control point (within radius_px), both coordinates
    double radius_px = 8;
};
enum class SnapKind { none, grid, axis, point };
struct Snapped2 {
    glm::dvec2 p{0};
    SnapKind kind[2] = {SnapKind::none, SnapKind::none};
    int point = -1; // the index in `others` it landed on, or -1
};
// A point dragged on a plane canvas with `units_per_px` (world units per pixel): first the
// nearest of `others` within the radius (exactly its coordinates), else per coordinate the
// axis within the radius, else the nearest of `others`' same coordinate within the radius
// (aligned with it: kind point, `point` stays -1), else the grid value (when grid is on),
// else as it is.
Snapped2 snap_plane_point(const glm::dvec2& p, const SnapSettings& s, GridStep step,
                          double units_per_px, const std::vector<glm::dvec2>& others);
// The same in 3D (the 3D view's drag): `others` are compared by their screen distance
// (`screen` of the dragged point's pixel and `others_px` theirs, both in pixels); the
// coordinates listed in `free_axes` (the ones the drag moves: all three in the view plane, one
// along an axis) snap to the axis or the grid, the others keep their value.
struct Snapped3 {
    glm::dvec3 p{0};
    int point = -1;
    bool snapped = false;
};
Snapped3 snap_space_point(const glm::dvec3& p, const glm::dvec2& screen, const SnapSettings& s,
                          GridStep step, double units_per_px, const bool free_axes[3],
                          const std::vector<glm::dvec3>& others,
                          const std::vector<glm::dvec2>& others_px);

} // namespace isoparm::ui
