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
// together when the total would pass max_display_vertices; at least 2 per direction.
inline std::pair<int, int> display_samples(const geom::Surface& s, int density) {
    density = std::clamp(density, 2, 256);
    double su = nonempty_spans(s.knots_u, s.degree_u, s.n_u) * static_cast<double>(density) + 1;
    double sv = nonempty_spans(s.knots_v, s.degree_v, s.n_v) * static_cast<double>(density) + 1;
    const double total = su * sv;
    if (total > static_cast<double>(max_display_vertices)) {
        const double f = std::sqrt(static_cast<double>(max_display_vertices) / total);
        su = std::floor(su * f);
        sv = std::floor(sv * f);
    }
    return {std::max(static_cast<int>(su), 2), std::max(static_cast<int>(sv), 2)};
}

} // namespace isoparm::ui
