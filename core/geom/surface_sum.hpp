// Sums of polynomial surfaces over one domain: the boolean sums of Coons and Gordon patches.
#pragma once

#include <utility>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// sum of factor * surface, exactly: each term is raised to the largest degrees (A5.9) and
// refined to the union of the knot vectors, every knot at its largest multiplicity (A5.1), so
// that one control net serves all and the sum is taken control point by control point.
// Preconditions: unit weights, clamped knots, the same domain. A result above the size caps
// is `limit` (no path).
Expected<Surface> sum_of_surfaces(const std::vector<std::pair<double, Surface>>& terms);

} // namespace isoparm::geom
