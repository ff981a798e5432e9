// A B-spline or NURBS continued past the ends of its domain: the first and last pieces'
// polynomials (rational functions, in homogeneous space) carried on, so the object is unchanged
// on its old domain and is, outside it, what evaluating the end pieces beyond their spans gives
// (OpenCASCADE's evaluation of a B-spline outside its range, which is what its area and
// meshing integrate over a face whose p-curves leave the surface's domain).
#pragma once

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The curve over `to` (which holds its domain): its end knots moved to to.lo and to.hi and its
// first and last p control points replaced by the end pieces' blossoms at the new knots
// (P_i = f(U'[i+1], ..., U'[i+p]); Ramshaw, Piegl & Tiller sec. 5.5): the interior knots and
// control points are kept. Errors: `schema` where the knots are not clamped at both ends,
// `domain` where `to` does not hold the domain or is not finite, `weights` where a rational
// continuation needs a control weight that is not positive (its weight may reach zero, a point
// at infinity, within `to`). Control points that are kept are kept bit for bit.
Expected<Curve> extend_domain(const Curve& c, Interval to);
// The same in u over to.u, then in v over to.v (each row, then each column, of control points).
Expected<Surface> extend_domain(const Surface& s, const ParamRect& to);

} // namespace isoparm::geom
