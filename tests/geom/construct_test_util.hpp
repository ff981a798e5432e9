// Shared helpers for the construction tests: sampling grids and curve maps to [0, 1].
#pragma once

#include <glm/geometric.hpp>
#include <vector>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/types.hpp"

namespace isoparm::testing {

// n + 1 parameters spanning [lo, hi] with both ends exact.
inline std::vector<double> samples(double lo, double hi, int n) {
    std::vector<double> t(n + 1);
    for (int k = 0; k <= n; ++k) t[k] = k == n ? hi : lo + (hi - lo) * k / n;
    return t;
}

// The curve's point at s in [0, 1] of its own domain (what make_compatible maps to s).
inline std::optional<glm::dvec3> point_at_unit(const geom::Curve& c, double s) {
    const geom::Interval d = geom::domain(c);
    return geom::curve_point(c, s >= 1.0 ? d.hi : d.lo + (d.hi - d.lo) * s);
}

inline double net_size(const geom::Curve& c) {
    double m = 1;
    for (auto& p : c.points) m = std::max(m, glm::length(p));
    return m;
}

} // namespace isoparm::testing
