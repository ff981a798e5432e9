// Edits that change the shape on purpose, as DesignMentor's curve system offered them: closing
// a curve periodically, and splitting a multiple knot.
#pragma once

#include <optional>
#include <string>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The closed (periodic) curve of the same control polygon: the first p control points (and
// weights) repeated at the end, unclamped uniform knots (k - p) / n for n original points, so
// the domain [knots[p], knots[n]] of the new count is [0, 1] and the ends meet with
// C^(p-1) continuity. The shape is a new one: the polygon is now closed. Bezier types become
// bspline (rational ones nurbs).
Curve close_periodic(const Curve& c);
// Each line along `dir` closed the same way.
Surface close_periodic(const Surface& s, Dir dir);
// Whether c is closed exactly as close_periodic closes: knots (k - p) / n for its n + p points
// and the last p control points (and weights) equal to the first p.
bool is_closed_periodic(const Curve& c);

// DesignMentor's knot splitting: the control points stay and the first copy of `knot` (of
// multiplicity m >= 2) moves to knot - delta, so `knot` keeps m - 1 copies and a simple knot
// appears just before it; the shape changes slightly. delta defaults to 1% of the span before
// the knot. Errors (`schema`): a value that is not a knot, or is simple, or has no knot before
// it ("/knot"); delta not > 0 or reaching the previous distinct knot ("/delta").
// max_change is the supremum of the distance between old and new over their common domain
// (at a knot of multiplicity p + 1, where the curve jumps, the limit from the side where it is
// largest), measured piece by piece; its cost is charged to the work budget first (`limit` at
// `budget_path` when a high degree makes it too costly).
template <class Shape> struct KnotSplit {
    Shape result;
    double max_change = 0;
};
Expected<KnotSplit<Curve>> split_knot(const Curve& c, double knot, std::optional<double> delta,
                                      const std::string& budget_path = "");
Expected<KnotSplit<Surface>> split_knot(const Surface& s, Dir dir, double knot,
                                        std::optional<double> delta,
                                        const std::string& budget_path = "");

} // namespace isoparm::geom
