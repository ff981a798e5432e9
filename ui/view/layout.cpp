// Window layout maths: columns, stacked panels and splitter drags.
#include "ui/view/layout.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace isoparm::ui {

namespace {

// Splits `total` pixels into rows by shares, with `gap` between rows; each row keeps
// `min_h` when the total allows it.
std::vector<float> row_heights(const std::vector<float>& shares, float total, float gap,
                               float min_h) {
    const int n = static_cast<int>(shares.size());
    std::vector<float> h(n, 0.f);
    if (n == 0) return h;
    const float avail = std::max(total - gap * static_cast<float>(n - 1), 0.f);
    const float sum = std::accumulate(shares.begin(), shares.end(), 0.f);
    for (int k = 0; k < n; ++k) h[k] = avail * (sum > 0 ? shares[k] / sum : 1.f / n);
    if (avail < min_h * static_cast<float>(n)) return h; // too small: proportional only
    // Lift rows below the minimum, taking the height from the rows that have spare.
    for (int pass = 0; pass < n; ++pass) {
        float deficit = 0, spare = 0;
        for (int k = 0; k < n; ++k) {
            if (h[k] < min_h)
                deficit += min_h - h[k];
            else
                spare += h[k] - min_h;
        }
        if (deficit <= 0) break;
        for (int k = 0; k < n; ++k) {
            if (h[k] < min_h)
                h[k] = min_h;
            else
                h[k] -= (h[k] - min_h) / spare * deficit;
        }
    }
    return h;
}

void stack(const std::vector<float>& shares, float x, float y, float w, float total, float gap,
           float min_h, std::vector<Rect>& panels, std::vector<Rect>& splitters) {
    const std::vector<float> h = row_heights(shares, total, gap, min_h);
    float cy = y;
    for (std::size_t k = 0; k < h.size(); ++k) {
        panels.push_back({x, cy, w, h[k]});
        cy += h[k];
        if (k + 1 < h.size()) {
            splitters.push_back({x, cy, w, gap});
            cy += gap;
        }
    }
}

std::vector<float> sane_shares(const std::vector<float>& s, const std::vector<float>& fallback) {
    if (s.size() != fallback.size()) return fallback;
    for (float x : s)
        if (!std::isfinite(x) || x <= 0) return fallback;
    return s;
}

} // namespace

Layout compute_layout(const LayoutPrefs& prefs, const LayoutInput& in) {
    Layout out;
    const float s = in.scale;
    const float gap = in.splitter;
    const float avail = std::max(in.width - 2 * gap, 0.f);
    const float height = std::max(in.height - in.top - in.bottom, 0.f);
    const float min_side = min_side_width * s;
    const float min_center = std::max(min_center_width * s, in.min_center_fraction * avail);

    float l = std::max(prefs.left_width * s, min_side);
    float r = std::max(prefs.right_width * s, min_side);
    if (l + r + min_center > avail) {
        if (2 * min_side + min_center <= avail) {
            // Shrink the side columns' extra width proportionally until the centre fits.
            const float excess = l + r + min_center - avail;
            const float extra = (l - min_side) + (r - min_side);
            l -= (l - min_side) / extra * excess;
            r -= (r - min_side) / extra * excess;
        } else if (in.min_center_fraction > 0) {
            // A small window (a projector's 1024x768 in presentation mode): the centre keeps
            // its share, since the class looks at it; the columns split the rest.
            const float sides = avail * (1 - std::min(in.min_center_fraction, 1.f));
            const float total = l + r;
            l = sides * l / total;
            r = sides * r / total;
        } else {
            // A tiny window: keep the default proportions.
            const float total = l + r + min_center;
            l = avail * l / total;
            r = avail * r / total;
        }
    }
    if (in.presentation && prefs.presentation_left > 0 && prefs.presentation_right > 0) {
        // The columns the user dragged in presentation mode, while the centre keeps its minimum.
        const float side_min = std::min(min_side, avail * 0.15f);
        const float centre_min = std::min(min_center_width * s, avail * 0.3f);
        l = std::max(prefs.presentation_left * avail, side_min);
        r = std::max(prefs.presentation_right * avail, side_min);
        if (l + r + centre_min > avail) {
            const float excess = l + r + centre_min - avail;
            const float extra = std::max((l - side_min) + (r - side_min), 1e-3f);
            l -= (l - side_min) / extra * excess;
            r -= (r - side_min) / extra * excess;
        }
    }
    const float c = std::max(avail - l - r, 0.f);

    const float y = in.top;
    out.left_splitter = {l, y, gap, height};
    out.center = {l + gap, y, c, height};
    out.right_splitter = {l + gap + c, y, gap, height};
    const float rx = l + 2 * gap + c;
    const float min_h = min_row_height * s;
    stack(prefs.left_shares, 0, y, l, height, gap, min_h, out.left, out.left_row_splitters);
    stack(prefs.right_shares, rx, y, in.width - rx, height, gap, min_h, out.right,
          out.right_row_splitters);
    return out;
}

void drag_column_splitter(LayoutPrefs& prefs, const Layout& layout, const LayoutInput& in,
                          Side side, float dx) {
    const float s = in.scale > 0 ? in.scale : 1.f;
    if (in.presentation) {
        const float avail = std::max(in.width - 2 * in.splitter, 1.f);
        float l = layout.left_splitter.x;
        float r = in.width - (layout.right_splitter.x + layout.right_splitter.w);
        if (side == Side::left)
            l += dx;
        else
            r -= dx;
        const float side_min = std::min(min_side_width * s, avail * 0.15f);
        const float centre_min = std::min(min_center_width * s, avail * 0.3f);
        l = std::clamp(l, side_min, std::max(side_min, avail - r - centre_min));
        r = std::clamp(r, side_min, std::max(side_min, avail - l - centre_min));
        prefs.presentation_left = l / avail;
        prefs.presentation_right = r / avail;
        return;
    }
    if (side == Side::left) {
        const float w = layout.left_splitter.x + dx;
        prefs.left_width = std::max(w / s, min_side_width);
    } else {
        const float w = in.width - (layout.right_splitter.x + layout.right_splitter.w) - dx;
        prefs.right_width = std::max(w / s, min_side_width);
    }
}

void drag_row_splitter(LayoutPrefs& prefs, const Layout& layout, const LayoutInput& in, Side side,
                       int index, float dy) {
    std::vector<float>& shares = side == Side::left ? prefs.left_shares : prefs.right_shares;
    const std::vector<Rect>& rows = side == Side::left ? layout.left : layout.right;
    if (index < 0 || index + 1 >= static_cast<int>(rows.size()) || rows.size() != shares.size())
        return;
    const float min_h = min_row_height * in.scale;
    float a = rows[index].h, b = rows[index + 1].h;
    const float pair = a + b;
    if (pair < 2 * min_h) return; // no room to move
    a = std::clamp(a + dy, min_h, pair - min_h);
    b = pair - a;
    // Re-express every row as its laid-out height, so untouched rows keep their size.
    for (std::size_t k = 0; k < rows.size(); ++k) shares[k] = rows[k].h;
    shares[index] = a;
    shares[index + 1] = b;
    const float sum = std::accumulate(shares.begin(), shares.end(), 0.f);
    for (float& x : shares) x /= sum;
}

LayoutPrefs sanitize(const LayoutPrefs& prefs) {
    const LayoutPrefs def;
    LayoutPrefs out = prefs;
    if (!std::isfinite(out.left_width) || out.left_width < min_side_width || out.left_width > 4000)
        out.left_width = def.left_width;
    if (!std::isfinite(out.right_width) || out.right_width < min_side_width ||
        out.right_width > 4000)
        out.right_width = def.right_width;
    out.left_shares = sane_shares(out.left_shares, def.left_shares);
    const bool shares_ok = std::isfinite(out.presentation_left) &&
                           std::isfinite(out.presentation_right) && out.presentation_left > 0 &&
                           out.presentation_right > 0 &&
                           out.presentation_left + out.presentation_right < 0.9f;
    if (!shares_ok) out.presentation_left = out.presentation_right = 0;
    out.right_shares = sane_shares(out.right_shares, def.right_shares);
    return out;
}

} // namespace isoparm::ui
