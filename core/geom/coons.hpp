// The bilinearly blended Coons patch from four boundary curves (Piegl & Tiller 10.5; Farin,
// "Curves and Surfaces for CAGD", ch. 22).
#pragma once

#include <array>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// curves = [C_u0, C_u1, C_0v, C_1v]: S(u, 0), S(u, 1), S(0, v), S(1, v), each mapped to [0, 1].
// S = R_u + R_v - T: the ruled surface between C_u0 and C_u1, plus the one between C_0v and
// C_1v, minus the bilinear patch of the corners, all raised to common degrees and knots; it
// reproduces the four boundaries exactly. Errors: a corner where two curves' ends are farther
// apart than 1e-9 of the network's size is `geometry` at the later of the two curves
// ("/curves/2" or "/curves/3"); rational boundaries whose weights are not all equal are
// `weights` at the curve ("/curves/k"): the blend of rational curves is not the sum of their
// control points.
Expected<Surface> coons(const std::array<Curve, 4>& curves);

// The surface with u and v exchanged: S'(u, v) = S(v, u).
Surface transposed(const Surface& s);

} // namespace isoparm::geom
