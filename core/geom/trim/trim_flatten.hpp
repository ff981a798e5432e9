// Trim loops as closed polylines in (u, v): adaptive chords within a tolerance measured in the
// domain or, for a mesh, on the surface in 3D.
#pragma once

#include <glm/vec2.hpp>
#include <limits>
#include <vector>

#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// How finely a loop is cut into chords. A chord is accepted when the curve strays from it by at
// most `tolerance` at a quarter, half and three quarters of its parameter interval: measured in
// (u, v), or, with `surface`, between the surface's point S(C(t)) and the 3D segment the chord
// becomes on the mesh. Every knot span gets at least one chord (two for degree > 1), none longer
// than `max_length` in (u, v), and no span is halved more than `max_depth` times.
struct FlattenRule {
    double tolerance = 1e-6;
    double max_length = std::numeric_limits<double>::infinity();
    const Surface* surface = nullptr;
    int max_depth = 20;
};

// A closed polyline: points[k] -> points[k + 1], the last back to the first (not repeated).
// curve[k] and param[k] say where each point lies on the loop (its curve and parameter), so a
// polyline point can be refined on its curve.
struct FlatLoop {
    std::vector<glm::dvec2> points;
    std::vector<int> curve;
    std::vector<double> param;
};

// Each curve's chords from its start, without its end point (the next curve's start; the loop's
// first point closes it, so gaps within the trim's closing tolerance vanish from the polyline).
// Precondition: a valid trim loop (positive weights, so every point exists).
FlatLoop flatten_loop(const TrimLoop& loop, const FlattenRule& rule);

// Twice the signed area the polyline encloses (shoelace): positive counter-clockwise.
double twice_signed_area(const std::vector<glm::dvec2>& polygon);

// The larger side of a domain: what the trim tolerances are fractions of.
double domain_scale(const ParamRect& domain);

} // namespace isoparm::geom
