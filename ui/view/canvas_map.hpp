// Pixel <-> parameter mappings for the 2D canvases (pure): the domain square, knot ticks,
// and the xy / xz / yz planes of the control-point panel.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/types.hpp"
#include "ui/view/layout.hpp"

namespace isoparm::ui {

// The domain square shows the normalised domain [0,1]^2 with u to the right and v upward,
// as in the paper's tracing window.
glm::dvec2 domain_to_pixel(const Rect& square, const glm::dvec2& uv);
// The inverse, clamped to [0,1]^2 (a drag past the edge pins the indicator to the edge).
glm::dvec2 pixel_to_domain(const Rect& square, const glm::dvec2& pixel);

// Between a parameter t of the interval and its normalised position in [0,1].
double normalize_param(const geom::Interval& d, double t);
double denormalize_param(const geom::Interval& d, double s);

// One distinct knot inside or at the ends of the domain, as a tick on the square's edge.
struct KnotTick {
    double value = 0;     // the knot
    double position = 0;  // normalised to [0,1] over the domain
    int multiplicity = 1; // counted exactly (never merged by tolerance)
    int first_index = 0;  // index of its first copy in the knot vector
    bool interior = false;
};
// The distinct knots of U within the domain [U[p], U[n]].
std::vector<KnotTick> knot_ticks(const geom::Knots& U, int p, int n);

// The tick nearest to `pixel_pos` along an edge within radius; positions are in pixels.
std::optional<std::size_t> hit_tick(const std::vector<double>& tick_px, double pixel_pos,
                                    double radius_px);

// A knot tick's handle in the tracing panel reaches this far either side of the tick along
// its edge (across, it spans the whole label strip): 9 px at scale 1 (an 18 px wide target,
// not the 2 px line drawn), 13.5 px in presentation mode, so a knot is easy to catch.
double knot_handle_radius(float scale);
// The tick under the pointer among those that can move (`movable[k]`; the domain's ends
// cannot): the nearest within radius, so a fixed end never shadows an interior knot.
std::optional<std::size_t> hit_movable_tick(const std::vector<double>& tick_px,
                                            const std::vector<bool>& movable, double pixel_pos,
                                            double radius_px);

// Labels on a canvas: ui/view/label_placer.hpp (the one placer of every view). A row of tick
// values can be thinned first: a label is kept when it is at least min_gap pixels from the
// last kept one; the two ends are always kept (the last end replaces a kept label that would
// crowd it). Input sorted ascending. (The figures' tick rows use it.)
std::vector<bool> thin_labels(const std::vector<double>& px, double min_gap);

// A 2D canvas showing world axes (ax, ay) at equal scale: the control-point panel's planes.
struct PlaneMap {
    Rect canvas;
    glm::dvec2 center{0, 0}; // world (a, b) at the canvas centre
    double units_per_px = 1;
};
// Fits the world box [lo, hi] (in the plane's two coordinates) with `margin_px` around it.
PlaneMap fit_plane(const Rect& canvas, const glm::dvec2& lo, const glm::dvec2& hi,
                   double margin_px);
// A plane canvas's kept framing (the curve designer, the Fit panel): the content's box [lo, hi]
// padded by max(pad_fraction * its span, 0.5) is framed when `same` is false (another object
// or plane) or the content left the kept box [frame_lo, frame_hi]; else the kept box stands,
// so a click does not shift the picture under the mouse. The whole visible area is kept, so a
// click anywhere on the canvas lands inside it.
PlaneMap kept_frame(glm::dvec2& frame_lo, glm::dvec2& frame_hi, bool same, const glm::dvec2& lo,
                    const glm::dvec2& hi, double pad_fraction, const Rect& canvas, double margin);
glm::dvec2 plane_to_pixel(const PlaneMap& m, const glm::dvec2& ab);
glm::dvec2 pixel_to_plane(const PlaneMap& m, const glm::dvec2& pixel);

// The axes of the three sub-views: xy, xz, yz.
struct PlaneAxes {
    int a, b;
    const char* name;
};
constexpr PlaneAxes plane_axes[3] = {{0, 1, "xy"}, {0, 2, "xz"}, {1, 2, "yz"}};

} // namespace isoparm::ui
