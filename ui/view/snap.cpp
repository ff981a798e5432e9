// Grid steps and snapping: exact decimal grid values, the nearest point, the axes.
#include "ui/view/snap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geom/status.hpp"

namespace isoparm::ui {

namespace {

// 10^e exactly (as a double: exact up to 10^22).
double power_of_ten(int e) {
    double p = 1;
    for (int k = 0; k < e; ++k) p *= 10;
    return p;
}

constexpr int max_exponent = 22; // 10^22 is the largest power of ten a double holds exactly

} // namespace

double GridStep::value() const {
    return grid_value(*this, 1);
}

GridStep grid_step_for(double pixels_per_unit, double min_pixels) {
    if (!(pixels_per_unit > 0) || !(min_pixels > 0)) return {};
    const double want = min_pixels / pixels_per_unit; // the smallest step in world units
    int e = static_cast<int>(std::floor(std::log10(want)));
    e = std::clamp(e, -max_exponent, max_exponent);
    for (int tries = 0; tries < 8; ++tries) {
        for (int m : {1, 2, 5}) {
            const GridStep s{m, e};
            if (s.value() >= want * (1 - 1e-12)) return s;
        }
        if (e == max_exponent) break;
        ++e;
    }
    return {5, max_exponent};
}

GridStep coarser(GridStep s) {
    if (s.mantissa == 1) return {2, s.exponent};
    if (s.mantissa == 2) return {5, s.exponent};
    return {1, std::min(s.exponent + 1, max_exponent)};
}

double grid_value(GridStep s, long long k) {
    const double km = static_cast<double>(k) * s.mantissa; // exact below 2^53
    const int e = std::clamp(s.exponent, -max_exponent, max_exponent);
    // One rounding: the product or the quotient of two exact numbers is the double nearest
    // the decimal k m 10^e.
    return e >= 0 ? km * power_of_ten(e) : km / power_of_ten(-e);
}

double snap_to_grid(double x, GridStep s) {
    if (!std::isfinite(x)) return x;
    const double step = s.value();
    const double q = x / step;
    if (!(std::abs(q) < 9e15)) return x; // beyond exact integers: leave it
    const auto k = static_cast<long long>(std::llround(q));
    // The rounded quotient can be one off near a half: keep the nearer of the neighbours.
    long long best = k;
    double best_d = std::abs(grid_value(s, k) - x);
    for (long long c : {k - 1, k + 1}) {
        const double d = std::abs(grid_value(s, c) - x);
        if (d < best_d) {
            best = c;
            best_d = d;
        }
    }
    return grid_value(s, best) + 0.0; // never -0.0
}

std::string grid_label(GridStep s, long long k) {
    return geom::format_number(grid_value(s, k) + 0.0);
}

GridRange grid_range(GridStep s, double lo, double hi) {
    const double step = s.value();
    if (!(hi >= lo) || !(step > 0)) return {};
    const double a = std::ceil(lo / step), b = std::floor(hi / step);
    if (!(std::abs(a) < 9e15) || !(std::abs(b) < 9e15)) return {};
    GridRange r{static_cast<long long>(a), static_cast<long long>(b)};
    // Rounding in the division (0.3 / 0.1 = 2.9999999999999996): the ends are found on the
    // values as grid_value makes them.
    while (grid_value(s, r.first - 1) >= lo) --r.first;
    while (grid_value(s, r.last + 1) <= hi) ++r.last;
    while (r.first <= r.last && grid_value(s, r.first) < lo) ++r.first;
    while (r.first <= r.last && grid_value(s, r.last) > hi) --r.last;
    return r;
}

Snapped2 snap_plane_point(const glm::dvec2& p, const SnapSettings& s, GridStep step,
                          double units_per_px, const std::vector<glm::dvec2>& others) {
    Snapped2 out;
    out.p = p;
    const double radius = s.radius_px * units_per_px;
    if (s.points) {
        double best = radius;
        for (std::size_t k = 0; k < others.size(); ++k) {
            const glm::dvec2 d = others[k] - p;
            const double dist = std::sqrt(d.x * d.x + d.y * d.y);
            if (dist <= best) {
                best = dist;
                out.point = static_cast<int>(k);
            }
        }
        if (out.point >= 0) {
            out.p = others[static_cast<std::size_t>(out.point)];
            out.kind[0] = out.kind[1] = SnapKind::point;
            return out;
        }
    }
    for (int a = 0; a < 2; ++a) {
        // Alignment: the nearest other point's coordinate within the radius (P1 straight above
        // P0), as a drawing program's guides do; it need not be a grid value.
        double aligned = 0, best = radius;
        bool align = false;
        if (s.points) {
            for (const glm::dvec2& o : others) {
                const double dist = std::abs(o[a] - p[a]);
                if (dist <= best) {
                    best = dist;
                    aligned = o[a];
                    align = true;
                }
            }
        }
        if (s.axes && std::abs(p[a]) <= radius) {
            out.p[a] = 0;
            out.kind[a] = SnapKind::axis;
        } else if (align) {
            out.p[a] = aligned;
            out.kind[a] = SnapKind::point;
        } else if (s.grid) {
            out.p[a] = snap_to_grid(p[a], step);
            out.kind[a] = SnapKind::grid;
        }
    }
    return out;
}

Snapped3 snap_space_point(const glm::dvec3& p, const glm::dvec2& screen, const SnapSettings& s,
                          GridStep step, double units_per_px, const bool free_axes[3],
                          const std::vector<glm::dvec3>& others,
                          const std::vector<glm::dvec2>& others_px) {
    Snapped3 out;
    out.p = p;
    if (s.points) {
        double best = s.radius_px;
        for (std::size_t k = 0; k < others.size() && k < others_px.size(); ++k) {
            const glm::dvec2 d = others_px[k] - screen;
            const double dist = std::sqrt(d.x * d.x + d.y * d.y);
            if (dist <= best) {
                best = dist;
                out.point = static_cast<int>(k);
            }
        }
        if (out.point >= 0) {
            out.p = others[static_cast<std::size_t>(out.point)];
            out.snapped = true;
            return out;
        }
    }
    const double radius = s.radius_px * units_per_px;
    for (int a = 0; a < 3; ++a) {
        if (!free_axes[a]) continue;
        if (s.axes && std::abs(p[a]) <= radius) {
            out.p[a] = 0;
            out.snapped = true;
        } else if (s.grid) {
            out.p[a] = snap_to_grid(p[a], step);
            out.snapped = true;
        }
    }
    return out;
}

} // namespace isoparm::ui
