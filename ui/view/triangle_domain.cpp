// The triangular patch's teaching panels without ImGui (Farin ch. 17).
#include "ui/view/triangle_domain.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>

#include "core/geom/status.hpp"

namespace isoparm::ui {

namespace {

const char* coordinate_name(int which) {
    static const char* names[3] = {"r", "s", "t"};
    return names[which];
}

} // namespace

geom::Barycentric triangle_grid_point(int N, int a, int b) {
    const double n = N;
    return {a / n, b / n, (N - a - b) / n};
}

TriangleWeightsKey TriangleWeightsKey::of(const geom::TrianglePatch& t, int subdivisions) {
    return {t.degree, t.rational, t.weights, subdivisions};
}

bool TriangleWeightsKey::matches(const geom::TrianglePatch& t, int subdivisions_) const {
    return degree == t.degree && rational == t.rational && subdivisions == subdivisions_ &&
           weights == t.weights;
}

const geom::TrianglePatch* selected_triangle(const doc::Document& d, const doc::Object** object) {
    const doc::Object* o = d.selected();
    const geom::TrianglePatch* t = o ? o->triangle() : nullptr;
    if (object) *object = t ? o : nullptr;
    return t;
}

TriangleCanvas fit_triangle(const Rect& box, double margin) {
    const double w = std::max(box.w - 2 * margin, 1.0), h = std::max(box.h - 2 * margin, 1.0);
    const double height_per_side = std::sqrt(3.0) / 2;
    const double side = std::min(w, h / height_per_side), height = side * height_per_side;
    const double cx = box.x + box.w / 2.0;
    const double bottom = box.y + box.h / 2.0 + height / 2;
    TriangleCanvas c;
    c.vertex[0] = {cx + side / 2, bottom};
    c.vertex[1] = {cx, bottom - height};
    c.vertex[2] = {cx - side / 2, bottom};
    return c;
}

glm::dvec2 barycentric_to_pixel(const TriangleCanvas& c, const geom::Barycentric& p) {
    return p[0] * c.vertex[0] + p[1] * c.vertex[1] + p[2] * c.vertex[2];
}

geom::Barycentric pixel_to_barycentric(const TriangleCanvas& c, const glm::dvec2& pixel) {
    // pixel - T = r (R - T) + s (S - T), solved by Cramer's rule; t = 1 - r - s.
    const glm::dvec2 a = c.vertex[0] - c.vertex[2], b = c.vertex[1] - c.vertex[2];
    const glm::dvec2 d = pixel - c.vertex[2];
    const double det = a.x * b.y - a.y * b.x;
    if (det == 0) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
    const double r = (d.x * b.y - d.y * b.x) / det, s = (a.x * d.y - a.y * d.x) / det;
    return {r, s, 1 - r - s};
}

std::optional<std::pair<int, int>> domain_point_at(const TriangleCanvas& c, int n,
                                                   const glm::dvec2& pixel, double radius) {
    std::optional<std::pair<int, int>> best;
    double best_distance = radius;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; i + j <= n; ++j) {
            const glm::dvec2 at =
                barycentric_to_pixel(c, {static_cast<double>(i) / n, static_cast<double>(j) / n,
                                         static_cast<double>(n - i - j) / n});
            const double d = glm::distance(at, pixel);
            if (d <= best_distance) {
                best_distance = d;
                best = std::pair(i, j);
            }
        }
    return best;
}

geom::Barycentric clamp_to_triangle(const geom::Barycentric& p) {
    if (p[0] >= 0 && p[1] >= 0 && p[2] >= 0) return p;
    // Michelot: the projection is max(p - theta, 0) with theta chosen so the result sums to
    // 1; theta comes from the largest coordinates, taken in decreasing order.
    std::array<double, 3> sorted = p;
    std::sort(sorted.begin(), sorted.end(), std::greater<>());
    double partial = 0, theta = 0;
    for (int k = 0; k < 3; ++k) {
        partial += sorted[k];
        const double candidate = (partial - 1) / (k + 1);
        if (sorted[k] - candidate > 0) theta = candidate;
    }
    geom::Barycentric q;
    for (int k = 0; k < 3; ++k) q[k] = std::max(p[k] - theta, 0.0);
    return q;
}

geom::Expected<geom::Barycentric> set_barycentric_coordinate(const geom::Barycentric& p, int which,
                                                             double value) {
    const std::string name = coordinate_name(which);
    if (!std::isfinite(value) || value < 0 || value > 1)
        return geom::make_error(geom::ErrorCode::domain,
                                name + " = " + geom::format_number(value) +
                                    " is outside the triangle: r, s and t are each between 0 "
                                    "and 1, and they sum to 1",
                                "/" + name);
    const int a = (which + 1) % 3, b = (which + 2) % 3;
    const double rest = 1 - value, others = p[a] + p[b];
    geom::Barycentric q = p;
    q[which] = value;
    q[a] = others > 0 ? std::min(rest * p[a] / others, rest) : rest / 2;
    q[b] = std::max(rest - q[a], 0.0);
    return q;
}

std::string triangle_point_name(int n, int level, int i, int j) {
    const int k = n - level - i - j;
    const std::string sep = n < 10 ? "" : ",";
    const std::string indices =
        std::to_string(i) + sep + std::to_string(j) + sep + std::to_string(k);
    return level == 0 ? "b" + indices : "b^" + std::to_string(level) + "_" + indices;
}

int triangle_level_size(int n, int level) {
    return geom::TrianglePatch::count_for(n - level);
}

std::string triangle_step_text(int step, int n) {
    if (step < 0) return "all levels";
    if (step == 0)
        return "the " + std::to_string(triangle_level_size(n, 0)) + " control points b_ijk";
    const std::string level = "level " + std::to_string(step);
    if (step >= n) return level + ", the patch point S(r, s, t) = b^" + std::to_string(n) + "_000";
    return level + ", the " + std::to_string(triangle_level_size(n, step)) + " points b^" +
           std::to_string(step) + "_ijk with i + j + k = " + std::to_string(n - step);
}

std::vector<std::vector<double>> triangle_level_weights(const geom::TrianglePatch& t,
                                                        const geom::Barycentric& p) {
    // The scalar de Casteljau step on the weights alone: w^l_ijk = r w^(l-1)_(i+1)jk +
    // s w^(l-1)_i(j+1)k + t w^(l-1)_ij(k+1), the last coordinate of Farin 17.3 in homogeneous
    // space.
    using geom::TrianglePatch;
    std::vector<std::vector<double>> levels{t.weights};
    for (int m = t.degree - 1; m >= 0; --m) {
        const std::vector<double>& w = levels.back();
        std::vector<double> next(static_cast<std::size_t>(TrianglePatch::count_for(m)));
        for (int i = m; i >= 0; --i)
            for (int j = m - i; j >= 0; --j)
                next[TrianglePatch::index(m, i, j)] =
                    p[0] * w[TrianglePatch::index(m + 1, i + 1, j)] +
                    p[1] * w[TrianglePatch::index(m + 1, i, j + 1)] +
                    p[2] * w[TrianglePatch::index(m + 1, i, j)];
        levels.push_back(std::move(next));
    }
    return levels;
}

bool same_heat(const TriangleHeat& heat, const geom::TrianglePatch& t, int i, int j,
               int subdivisions) {
    return heat.valid && heat.i == i && heat.j == j && heat.key.matches(t, subdivisions);
}

TriangleHeat triangle_heat(const geom::TrianglePatch& t, int i, int j, int subdivisions) {
    TriangleHeat h;
    h.key = TriangleWeightsKey::of(t, subdivisions);
    h.i = i;
    h.j = j;
    const int N = subdivisions;
    h.values.assign(static_cast<std::size_t>(geom::TrianglePatch::count_for(N)), std::nan(""));
    bool any = false, positive = false, negative = false;
    for (int a = N; a >= 0; --a)
        for (int b = N - a; b >= 0; --b) {
            const geom::Barycentric q = triangle_grid_point(N, a, b);
            if (t.rational) {
                const double w = geom::triangle_denominator(t, q);
                positive |= !(w <= 0); // a NaN weight sum counts as vanishing too
                negative |= !(w >= 0);
                h.denominator_vanishes |= w == 0 || (positive && negative);
            }
            const auto R = geom::rational_bernstein_triangle(t, i, j, q);
            if (!R) continue;
            h.values[static_cast<std::size_t>(geom::TrianglePatch::index(N, a, b))] = *R;
            h.largest = any ? std::max(h.largest, *R) : *R;
            h.largest_magnitude = std::max(h.largest_magnitude, std::abs(*R));
            any = true;
        }
    h.valid = true;
    return h;
}

BasisPeak triangle_basis_peak(const geom::TrianglePatch& t, int i, int j, const TriangleHeat& heat,
                              bool lowest) {
    const int n = t.degree;
    const double sign = lowest ? -1 : 1; // the lowest value is the peak of -R
    BasisPeak peak;
    const bool unit_weights = std::all_of(t.weights.begin(), t.weights.end(),
                                          [&](double w) { return w == t.weights[0] && w != 0; });
    if (!lowest && (!t.rational || unit_weights)) {
        // Equal weights cancel: R_ijk = B^n_ijk, whose peak is known.
        peak.at = triangle_grid_point(n, i, j);
        peak.value = geom::bernstein_triangle(n, i, j, peak.at);
        peak.exact = peak.found = true;
        return peak;
    }
    if (heat.denominator_vanishes) {
        peak.unbounded = true; // a search would only run towards the pole
        return peak;
    }
    // The best grid point, then a compass search from there.
    const int N = heat.key.subdivisions;
    for (int a = N; a >= 0; --a)
        for (int b = N - a; b >= 0; --b) {
            const double v =
                heat.values[static_cast<std::size_t>(geom::TrianglePatch::index(N, a, b))];
            if (std::isnan(v) || (peak.found && sign * v <= sign * peak.value)) continue;
            peak = {triangle_grid_point(N, a, b), v, false, true};
        }
    if (!peak.found) return peak;
    static const int directions[6][3] = {{1, -1, 0}, {-1, 1, 0}, {1, 0, -1},
                                         {-1, 0, 1}, {0, 1, -1}, {0, -1, 1}};
    for (double step = 1.0 / N; step > 1e-10; step /= 2) {
        // Each move raises the value (lowers it, for the lowest); the bound only guards against a
        // plateau of equal values that rounding makes look like a rise.
        int moves = 0;
        for (bool moved = true; moved && moves < 1000; ++moves) {
            moved = false;
            for (const auto& d : directions) {
                geom::Barycentric q = peak.at;
                for (int c = 0; c < 3; ++c) q[c] += step * d[c];
                if (q[0] < 0 || q[1] < 0 || q[2] < 0) continue;
                const auto v = geom::rational_bernstein_triangle(t, i, j, q);
                if (v && sign * *v > sign * peak.value) {
                    peak.at = q;
                    peak.value = *v;
                    moved = true;
                }
            }
        }
    }
    return peak;
}

} // namespace isoparm::ui
