// Knot removal (Piegl & Tiller 5.4, A5.8 RemoveCurveKnot), for curves and surfaces, within a
// tolerance measured against the original shape.
#pragma once

#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"
#include "core/geom/work_budget.hpp"

namespace isoparm::geom {

// One removal of the knot U[r] (r the index of its last copy, strictly inside the domain) from
// the homogeneous curve (p, U, Pw): A5.8 with num = 1. Of the p - s + 1 equations of knot
// insertion (eq. 5.28 solved from the left, eq. 5.29 from the right) for the p - s new points,
// each is used from the end that divides by the larger factor (the book meets in the middle;
// this rounds less where knots crowd) and the one left over is A5.8's test: `distance` is how
// far its old point would move if the knot were inserted back (in 4D with the weights, else in
// 3D); at multiplicity p + 1, the distance between the two points on either side of the gap.
// That one point is all that changes, so the curve (homogeneous, for a rational curve) moves by
// at most `distance`, and only on its support [moved_from, moved_to].
struct OneKnotRemoval {
    Knots knots;
    std::vector<HPoint> points;
    double distance = 0;
    double moved_from = 0, moved_to = 0;
};
OneKnotRemoval remove_knot_once(int p, const Knots& U, const std::vector<HPoint>& Pw, int r,
                                bool with_weights);

// From distances in homogeneous space to model units for a rational curve with these control
// points (Piegl & Tiller eq. 5.30). If the homogeneous curve moves by at most e, the curve moves
// by at most e (1 + |P|_max) / (w_min - e): the weight function stays above w_min - e and the
// curve inside the ball of radius |P|_max. homogeneous_tolerance is its inverse, the 4D
// tolerance d w_min / (1 + |P|_max + d) for d in model units (the book's d w_min / (1 + |P|_max)
// drops the last d). No bound is known (infinity; tolerance 0) when a weight is zero or negative
// or e >= w_min. Non-rational curves: distances are model units.
double cartesian_bound(double homogeneous_bound, const std::vector<glm::dvec3>& points,
                       const std::vector<double>& weights, bool rational);
double homogeneous_tolerance(double tolerance, const std::vector<glm::dvec3>& points,
                             const std::vector<double>& weights, bool rational);

// The knot `knot` removed up to `times` times, one removal at a time: each must pass A5.8's test
// (its distance, scaled by eq. 5.30 for rational curves, within `tolerance`) and the result,
// sampled densely on the part of the domain the removals can change, must stay within
// `tolerance` of the original (max_deviation: the largest sampled distance). The first removal
// that fails either test stops the loop: `removed` may be below `times` (0 when the knot is
// essential). A surface removes the knot from every line along `dir`; a removal counts only if
// every line passes, and the deviation is sampled on the surface.
// Errors (paths of the protocol's request): a knot outside the domain or at one of its ends
// (`domain`, "/knot"); a value inside it that is not a knot (`schema`, "/knot"); times < 1
// (`schema`, "/times"); a negative or non-finite tolerance (`schema`, "/tolerance").
struct CurveKnotRemoval {
    Curve curve;
    int removed = 0;
    double max_deviation = 0;
};
struct SurfaceKnotRemoval {
    Surface surface;
    int removed = 0;
    double max_deviation = 0;
};
Expected<CurveKnotRemoval> remove_knot(const Curve& c, double knot, int times, double tolerance);
Expected<SurfaceKnotRemoval> remove_knot(const Surface& s, Dir dir, double knot, int times,
                                         double tolerance);

// The work of the calls above with the same arguments, for the work budget (work_budget.hpp):
// the sampled evaluations of the original and of every candidate, and the removals themselves.
// Arguments the calls refuse cost nothing.
WorkEstimate knot_removal_cost(const Curve& c, double knot, int times);
WorkEstimate knot_removal_cost(const Surface& s, Dir dir, double knot, int times);

} // namespace isoparm::geom
