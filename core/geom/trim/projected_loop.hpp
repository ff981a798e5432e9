// The trim loop a closed curve drawn in a plane cuts on a surface when it is projected along
// the plane's normal (what Rhino's Project does along the construction plane's normal).
#pragma once

#include <glm/vec3.hpp>

#include "core/geom/status.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// For each parameter t of the closed curve c, the (u, v) where the line through C(t) along
// `direction` meets S: Newton's method on the two components of S(u, v) - C(t) across the
// direction, continued along t from the best point of a grid over the domain. The curve is cut
// at its kinks (interior knots of multiplicity >= degree) and each piece is fitted in (u, v) by
// fit_samples within `tolerance` (a fraction of the domain's larger side), so the loop has one
// cubic per smooth piece and closes exactly. The loop runs as the curve runs: the caller turns
// it round for a hole or an outer loop.
// Errors: a zero `direction` (schema, /direction); a curve whose ends are apart (geometry,
// /curve, naming the gap) or that has no point somewhere (weights, /curve); a point whose line
// misses the surface or meets it outside its domain (geometry, /curve, naming t and the point).
// Precondition: valid surface and curve.
Expected<TrimLoop> projected_loop(const Surface& s, const Curve& c, glm::dvec3 direction,
                                  double tolerance = 1e-6);

} // namespace isoparm::geom
