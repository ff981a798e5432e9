// Knot removal (Piegl & Tiller 5.4, A5.8 RemoveCurveKnot), for curves and surfaces, within a
// tolerance measured against the original shape.
#pragma once

#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"
#include "core/geom/work_budget.hpp"

namespace isoparm::geom {

// One removal of the knot U[r] (r the index of its last copy, strictly inside the domain) from
// the homogeneous curve (p, U, Pw): A5.8 with num = 1. The new points are computed from both
// ends (eq. 5.28, 5.29); where the two computations meet, the book's choice is kept (the one
// from the right). `distance` is A5.8's test, how far the two computations disagree (in 4D with
// the weights, else in 3D). Inserting the knot back would give the old points except one, which
// moves by at most `distance`; so the curve (homogeneous, for a rational curve) moves by at most
// `distance`, and only on [moved_from, moved_to].
struct OneKnotRemoval {
    Knots knots;
    std::vector<HPoint> points;
    double distance = 0;
    double moved_from = 0, moved_to = 0;
};
OneKnotRemoval remove_knot_once(int p, const Knots& U, const std::vector<HPoint>& Pw, int r,
                                bool with_weights);

// The largest distance a rational curve may move for each unit of homogeneous distance
// (Piegl & Tiller eq. 5.30: a tolerance d in model units is d w_min / (1 + |P|_max) in 4D):
// (1 + |P|_max) / w_min over the given points, infinite when a weight is zero or negative
// (no bound is known there); 1 for non-rational points.
double cartesian_per_homogeneous(const std::vector<glm::dvec3>& points,
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
