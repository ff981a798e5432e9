// Shape-preserving refinement: knot insertion, degree elevation, splitting.
#pragma once

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Inserts t `times` times (Boehm; Piegl & Tiller A5.1). t must lie in the domain (its ends
// included); the resulting multiplicity must not exceed the degree (error `multiplicity`,
// path "/times"); `domain` error path "/knot". A Bezier result with more than one span
// becomes bspline / nurbs.
Expected<Curve> insert_knot(const Curve& c, double t, int times = 1);
Expected<Surface> insert_knot(const Surface& s, Dir dir, double t, int times = 1);

// Piegl & Tiller A5.4 RefineKnotVectCurve on homogeneous points: inserts the sorted knots X
// (all strictly inside the domain) in one pass, O((n + r) p) instead of one Boehm pass per
// knot; it also reaches multiplicity p + 1. U and Pw are replaced by the refined ones.
void refine_knot_vector(int p, Knots& U, std::vector<HPoint>& Pw, const std::vector<double>& X);

// Raises the degree by `times` (Piegl & Tiller A5.9 on the clamped form; an unclamped
// vector is clamped first, which keeps the shape over the domain).
Expected<Curve> elevate_degree(const Curve& c, int times = 1);
Expected<Surface> elevate_degree(const Surface& s, Dir dir, int times = 1);

// Splits at t strictly inside the domain (error `domain`, path "/param"): the pieces keep
// their original parameters, [a, t] and [t, b], with t at multiplicity p + 1 in each.
Expected<std::pair<Curve, Curve>> split(const Curve& c, double t);
Expected<std::pair<Surface, Surface>> split(const Surface& s, Dir dir, double t);

// Clamps an unclamped curve at both domain ends without changing its shape on the domain.
Expected<Curve> clamp(const Curve& c);

// The control points in homogeneous form (w P, w), the space where knot insertion, removal and
// degree changes are linear; unit weights for non-rational types.
std::vector<HPoint> homogeneous_points(const Curve& c);

// From homogeneous points back to the Cartesian curve: a zero weight with non-zero
// weighted coordinates is a point at infinity (error `weights`, convention 6); a zero
// homogeneous point takes the position `fallback` gives (the same combination of the
// Cartesian points). Non-finite results are `weights` errors.
Expected<Curve> curve_from_homogeneous(const Curve& like, int degree, Knots knots,
                                       const std::vector<HPoint>& Pw,
                                       const std::vector<HPoint>* fallback);

} // namespace isoparm::geom
