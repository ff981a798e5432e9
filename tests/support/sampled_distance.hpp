// The largest distance between two curves or surfaces over a dense uniform sample of the first
// one's domain: an independent measure for operations that report how far they moved a shape.
#pragma once

#include <algorithm>
#include <glm/geometric.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/types.hpp"

namespace isoparm::testing {

inline double sampled_distance(const geom::Curve& a, const geom::Curve& b, int samples = 2000) {
    const geom::Interval d = geom::domain(a.knots, a.degree, a.count());
    double worst = 0;
    for (int k = 0; k <= samples; ++k) {
        const double t = k == samples ? d.hi : d.lo + (d.hi - d.lo) * k / samples;
        worst = std::max(worst, glm::distance(*geom::curve_point(a, t), *geom::curve_point(b, t)));
    }
    return worst;
}

inline double sampled_distance(const geom::Surface& a, const geom::Surface& b, int samples = 60) {
    const geom::Interval du = geom::domain(a.knots_u, a.degree_u, a.n_u);
    const geom::Interval dv = geom::domain(a.knots_v, a.degree_v, a.n_v);
    double worst = 0;
    for (int i = 0; i <= samples; ++i)
        for (int j = 0; j <= samples; ++j) {
            const double u = i == samples ? du.hi : du.lo + (du.hi - du.lo) * i / samples;
            const double v = j == samples ? dv.hi : dv.lo + (dv.hi - dv.lo) * j / samples;
            worst = std::max(
                worst, glm::distance(*geom::surface_point(a, u, v), *geom::surface_point(b, u, v)));
        }
    return worst;
}

} // namespace isoparm::testing
