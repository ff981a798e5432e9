// The 3D curve a trim curve traces on its surface, S(C(t)): what exchange files store beside
// the (u, v) curve as the edge's model-space geometry.
#pragma once

#include "core/geom/types.hpp"

namespace isoparm::geom {

// S(C(t)) over C's domain, with C's parameter: exact where C is a line of constant u or v (a
// piece of the surface's isocurve), otherwise a cubic least-squares fit (Piegl & Tiller 9.4.1,
// uniform parameters) refined until it is within `tolerance` of the surface at its samples and
// halfway between them. A curve that stays at one point (a pole) is a degree-1 curve there.
// Precondition: valid surface; C inside its domain with positive weights.
Curve curve_on_surface(const Surface& s, const Curve& uv, double tolerance);

} // namespace isoparm::geom
