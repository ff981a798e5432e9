// How finely the 3D view tessellates a surface: samples per direction from the document's
// density (header-only, so the core-only drag benchmark measures the very same policy).
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/geom/types.hpp"

namespace isoparm::ui {

// The vertex budget per surface: past it the grid coarsens evenly (a 32x32 bicubic surface
// has 29 spans a side; 32 samples per span would be ~860k vertices and stall every drag).
constexpr long max_display_vertices = 128L * 128L;

// Non-empty spans of a knot vector over its domain [U[p], U[n]].
inline int nonempty_spans(const geom::Knots& U, int p, int n) {
    int spans = 0;
    for (int k = p; k < n; ++k)
        if (U[k] < U[k + 1]) ++spans;
    return std::max(spans, 1);
}

// density samples per knot span in each direction (plus one to close the grid), scaled down
// together when the total would pass max_vertices; at least 2 per direction.
inline std::pair<int, int> display_samples(const geom::Surface& s, int density,
                                           long max_vertices = max_display_vertices) {
    density = std::clamp(density, 2, 256);
    double su = nonempty_spans(s.knots_u, s.degree_u, s.n_u) * static_cast<double>(density) + 1;
    double sv = nonempty_spans(s.knots_v, s.degree_v, s.n_v) * static_cast<double>(density) + 1;
    const double total = su * sv;
    if (total > static_cast<double>(max_vertices)) {
        const double f = std::sqrt(static_cast<double>(max_vertices) / total);
        su = std::floor(su * f);
        sv = std::floor(sv * f);
    }
    return {std::max(static_cast<int>(su), 2), std::max(static_cast<int>(sv), 2)};
}

// Gesture frames on a CPU rasteriser (ui/gesture_frames.hpp): while the mouse drags,
// a surface is drawn from at most 8 samples a span and 64 x 64 vertices. llvmpipe's cost there
// is its fill, and a fine grid's triangles of a few dozen pixels each are shaded in 4 x 4 blocks
// two or three times over along their edges: fig. 3b's hill at 1440 x 900 costs 13 ms of one
// core at 64 x 64 quads and about 7 at 16 x 16. Eight samples a span still bend a cubic span
// smoothly under per-vertex normals; the still frame after the release is drawn in full.
constexpr int gesture_density = 8;
constexpr long max_gesture_vertices = 64L * 64L;

inline std::pair<int, int> gesture_samples(const geom::Surface& s, int density) {
    return display_samples(s, std::min(density, gesture_density), max_gesture_vertices);
}

} // namespace isoparm::ui
