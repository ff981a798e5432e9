// What a rational spline is in homogeneous space, for teaching: the denominator w(u, v) of a
// surface and the curve in (u, v) where it vanishes (where the surface goes to infinity), an
// isocurve taken out as an exact curve, and a planar curve lifted to (w x, w y, w), where it is
// an ordinary polynomial B-spline that a central projection maps to the plane w = 1.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "core/geom/types.hpp"

namespace isoparm::geom {

// w(u, v) = sum N_i(u) N_j(v) w_ij, the denominator of the rational surface (1 for
// non-rational types, whose weights are all 1). Precondition: (u, v) in the domain.
double surface_denominator(const Surface& s, double u, double v);

// The zero set of w over the domain as segments in (u, v). Marching squares on a grid that
// holds every interior knot (w is a polynomial inside each knot cell, so the grid follows its
// pieces); ambiguous cells are split by the value at their centre; every crossing found on a
// cell edge is then refined by bisection on the exact w along that edge, so endpoints lie on
// w = 0 to rounding, not to the grid's resolution. `resolution` cells per direction at least.
// Grid values that are exactly 0 count as positive (the zero set then passes beside them).
struct ParamSegment {
    glm::dvec2 a, b;
};
std::vector<ParamSegment> denominator_zero_set(const Surface& s, int resolution = 64);

// The sign of w on a resolution x resolution grid of cell centres over the domain (u-major:
// entry iu * resolution + iv), +1, -1 or 0: what the tracing square tints.
std::vector<signed char> denominator_signs(const Surface& s, int resolution);

// S(t, .) for fixed = u (or S(., t) for fixed = v) as an exact curve: the homogeneous control
// points contracted with the fixed direction's basis at t (Piegl & Tiller sec. 3.4), degree
// and knots of the other direction, the surface's type. nullopt when a contracted control
// point is at infinity (its weights sum to exactly 0 while w P does not), which a Curve cannot
// hold. Precondition: t in the domain.
std::optional<Curve> isocurve(const Surface& s, Dir fixed, double t);

// The curve's coordinates `axes` (0 x, 1 y, 2 z: the plane it is seen in) lifted to
// homogeneous space as the non-rational curve with control points (w a, w b, w): its point at
// t divided by its third coordinate is the rational curve's point (where w != 0).
Curve homogeneous_lift(const Curve& c, std::array<int, 2> axes);

} // namespace isoparm::geom
