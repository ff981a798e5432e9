// Small hand-made surfaces whose denominators are known in closed form.
#pragma once

#include "core/geom/types.hpp"

namespace isoparm::testing {

// The unit square in z = 0 as a rational bilinear patch (degree 1 x 1, knots 0 0 1 1) with the
// corner weights w00, w01, w10, w11: w(u, v) = (1-u)(1-v) w00 + (1-u) v w01 + u (1-v) w10 +
// u v w11. Weights 1, 1, -1, -1 make w = 1 - 2u, exactly zero along u = 1/2.
inline geom::Surface bilinear_patch(double w00, double w01, double w10, double w11) {
    geom::Surface s;
    s.type = geom::SplineType::nurbs;
    s.degree_u = s.degree_v = 1;
    s.n_u = s.n_v = 2;
    s.knots_u = s.knots_v = {0, 0, 1, 1};
    s.points = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
    s.weights = {w00, w01, w10, w11};
    return s;
}

} // namespace isoparm::testing
