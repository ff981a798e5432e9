// Degree reduction within a tolerance (Piegl & Tiller 5.6, A5.11 DegreeReduceCurve).
#pragma once

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"
#include "core/geom/work_budget.hpp"

namespace isoparm::geom {

// The curve of degree p - 1 closest in A5.11's sense, and a bound on how far it lies from the
// original (max_error). As A5.11: the curve is cut into its Bezier pieces (knot refinement,
// A5.4; an unclamped curve is clamped first), each piece is reduced (eq. 5.41, 5.42) with its
// error bound (eq. 5.45 for even p, 5.46 for odd p), and each interior knot is removed back
// (A5.8) down to its multiplicity in the original minus one, the inverse of degree elevation
// (A5.9 raises every multiplicity by one): a simple knot disappears. Each removal adds its own
// bound to the knot spans it can move; max_error is the largest sum over the spans, in model
// units (for a rational curve the bound e in 4D turned into model units by eq. 5.30,
// cartesian_bound: e (1 + |P|_max) / (w_min - e); none is known with a weight <= 0 or e >=
// w_min, and the reduction is then refused unless e is exactly 0). A surface reduces
// every line along `dir` the same way; its bound is the largest of the lines'.
// Errors (paths of the protocol's request): degree 1 (`degree`, "/curve/degree",
// "/surface/degree/0" or "/1"); a negative or non-finite tolerance (`schema`, "/tolerance");
// a bound above the tolerance (`geometry`, "/curve" or "/surface", the bound in the message); a
// result with a control point at infinity (`weights`).
struct CurveDegreeReduction {
    Curve curve;
    double max_error = 0;
};
struct SurfaceDegreeReduction {
    Surface surface;
    double max_error = 0;
};
Expected<CurveDegreeReduction> reduce_degree(const Curve& c, double tolerance);
Expected<SurfaceDegreeReduction> reduce_degree(const Surface& s, Dir dir, double tolerance);

// The work of the calls above, for the work budget: 4 (p + 1)^2 + 200 steps for each Bezier
// piece of every line (about p control points each): refined into, reduced, and up to p - 1
// removals back, each copying a window of about 3p points.
WorkEstimate degree_reduction_cost(const Curve& c);
WorkEstimate degree_reduction_cost(const Surface& s, Dir dir);

} // namespace isoparm::geom
