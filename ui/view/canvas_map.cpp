// The 2D canvas mappings: domain square, knot ticks and label thinning, plane views.
#include "ui/view/canvas_map.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

#include "core/geom/knots.hpp"

namespace isoparm::ui {

glm::dvec2 domain_to_pixel(const Rect& sq, const glm::dvec2& uv) {
    return {sq.x + uv.x * sq.w, sq.y + (1.0 - uv.y) * sq.h};
}

glm::dvec2 pixel_to_domain(const Rect& sq, const glm::dvec2& px) {
    if (sq.w <= 0 || sq.h <= 0) return {0, 0};
    const double u = (px.x - sq.x) / sq.w;
    const double v = 1.0 - (px.y - sq.y) / sq.h;
    return {std::clamp(u, 0.0, 1.0), std::clamp(v, 0.0, 1.0)};
}

double normalize_param(const geom::Interval& d, double t) {
    const double len = d.hi - d.lo;
    return len > 0 ? (t - d.lo) / len : 0.0;
}

double denormalize_param(const geom::Interval& d, double s) {
    // Exact at both ends, so s = 1 gives the last knot bit for bit.
    if (s <= 0) return d.lo;
    if (s >= 1) return d.hi;
    return d.lo + (d.hi - d.lo) * s;
}

std::vector<KnotTick> knot_ticks(const geom::Knots& U, int p, int n) {
    std::vector<KnotTick> out;
    const geom::Interval d = geom::domain(U, p, n);
    for (const geom::KnotRun& run : geom::knot_runs(U)) {
        if (run.value < d.lo || run.value > d.hi) continue;
        KnotTick t;
        t.value = run.value;
        t.position = normalize_param(d, run.value);
        t.multiplicity = run.multiplicity;
        t.first_index = run.first_index;
        t.interior = run.value > d.lo && run.value < d.hi;
        out.push_back(t);
    }
    return out;
}

std::optional<std::size_t> hit_tick(const std::vector<double>& tick_px, double pixel_pos,
                                    double radius_px) {
    std::optional<std::size_t> best;
    double best_d = radius_px;
    for (std::size_t k = 0; k < tick_px.size(); ++k) {
        const double d = std::abs(tick_px[k] - pixel_pos);
        if (d <= best_d) {
            best = k;
            best_d = d;
        }
    }
    return best;
}

double knot_handle_radius(float scale) {
    return 9.0 * scale;
}

std::optional<std::size_t> hit_movable_tick(const std::vector<double>& tick_px,
                                            const std::vector<bool>& movable, double pixel_pos,
                                            double radius_px) {
    std::optional<std::size_t> best;
    double best_d = radius_px;
    for (std::size_t k = 0; k < tick_px.size() && k < movable.size(); ++k) {
        const double d = std::abs(tick_px[k] - pixel_pos);
        if (movable[k] && d <= best_d) {
            best = k;
            best_d = d;
        }
    }
    return best;
}

std::vector<bool> thin_labels(const std::vector<double>& px, double min_gap) {
    const std::size_t n = px.size();
    std::vector<bool> keep(n, false);
    if (n == 0) return keep;
    keep[0] = true;
    std::size_t last = 0;
    for (std::size_t k = 1; k + 1 < n; ++k) {
        if (px[k] - px[last] >= min_gap) {
            keep[k] = true;
            last = k;
        }
    }
    if (n > 1) {
        // The far end always shows; drop the previous kept label if it would crowd it.
        if (last != 0 && px[n - 1] - px[last] < min_gap) keep[last] = false;
        keep[n - 1] = true;
    }
    return keep;
}

PlaneMap fit_plane(const Rect& canvas, const glm::dvec2& lo, const glm::dvec2& hi,
                   double margin_px) {
    PlaneMap m;
    m.canvas = canvas;
    m.center = (lo + hi) * 0.5;
    const double span_a = std::max(hi.x - lo.x, 1e-9), span_b = std::max(hi.y - lo.y, 1e-9);
    const double w = std::max(canvas.w - 2 * margin_px, 1.0);
    const double h = std::max(canvas.h - 2 * margin_px, 1.0);
    // Equal scale on both axes, so shapes are not distorted.
    m.units_per_px = std::max(span_a / w, span_b / h);
    return m;
}

glm::dvec2 plane_to_pixel(const PlaneMap& m, const glm::dvec2& ab) {
    const double cx = m.canvas.x + m.canvas.w * 0.5, cy = m.canvas.y + m.canvas.h * 0.5;
    return {cx + (ab.x - m.center.x) / m.units_per_px, cy - (ab.y - m.center.y) / m.units_per_px};
}

glm::dvec2 pixel_to_plane(const PlaneMap& m, const glm::dvec2& px) {
    const double cx = m.canvas.x + m.canvas.w * 0.5, cy = m.canvas.y + m.canvas.h * 0.5;
    return {m.center.x + (px.x - cx) * m.units_per_px, m.center.y - (px.y - cy) * m.units_per_px};
}

PlaneMap kept_frame(glm::dvec2& frame_lo, glm::dvec2& frame_hi, bool same, const glm::dvec2& lo,
                    const glm::dvec2& hi, double pad_fraction, const Rect& canvas, double margin) {
    const bool inside =
        lo.x >= frame_lo.x && lo.y >= frame_lo.y && hi.x <= frame_hi.x && hi.y <= frame_hi.y;
    if (!same || !inside) {
        const double span = std::max(hi.x - lo.x, hi.y - lo.y);
        const glm::dvec2 pad(std::max(span * pad_fraction, 0.5));
        const glm::dvec2 box_lo = same ? glm::min(frame_lo, lo - pad) : lo - pad;
        const glm::dvec2 box_hi = same ? glm::max(frame_hi, hi + pad) : hi + pad;
        const PlaneMap m = fit_plane(canvas, box_lo, box_hi, margin);
        const glm::dvec2 c0 = pixel_to_plane(m, {canvas.x, canvas.y + canvas.h});
        const glm::dvec2 c1 = pixel_to_plane(m, {canvas.x + canvas.w, canvas.y});
        frame_lo = glm::min(c0, c1);
        frame_hi = glm::max(c0, c1);
    }
    return fit_plane(canvas, frame_lo, frame_hi, 0);
}

} // namespace isoparm::ui
