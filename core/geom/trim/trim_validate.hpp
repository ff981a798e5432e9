// Validation of trim loops against a surface's domain, with errors that name the loop, the
// curve and the problem.
#pragma once

#include <glm/vec2.hpp>
#include <optional>

#include "core/geom/status.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// Fractions of the domain's larger side (domain_scale): loop ends closer than trim_gap close
// the loop, a loop may stray this far outside the domain (files round their numbers); chords
// within trim_check_flatness of their curves decide crossings and orientation.
constexpr double trim_gap = 1e-7;
constexpr double trim_check_flatness = 1e-6;

// Paths are relative to the trim's JSON form: "/outer", "/holes/2" (a loop), "/holes/2/1" (its
// curve 1), "/holes/2/1/weights/3". Checks, in order, loop by loop (the outer loop first):
// - at least one curve; each curve valid (validate_curve) with positive weights (`weights`);
// - closed: each curve ends where the next starts, the last where the first starts, within
//   trim_gap (`geometry`, the curve that starts away from the previous end);
// - inside the domain within trim_gap (`domain`, the first curve that leaves it, with the point);
// - not crossing or touching itself (`geometry`, the two curves and where they meet);
// - enclosing some area, and oriented: the outer loop counter-clockwise, holes clockwise
//   (`geometry`);
// then between loops: no two cross or touch (`geometry`, both loops and the point), each hole
// inside the outer loop and outside every other hole (`geometry`).
Status validate_trim(const Trim& trim, const ParamRect& domain);

// Where two of the polylines' chords meet, for validation and its tests: the first crossing
// or touching of two segments that are not neighbours on the same loop (a segment's
// neighbours share its ends). loops[k] is closed (last point back to the first).
struct Crossing {
    int loop_a = 0, segment_a = 0, loop_b = 0, segment_b = 0;
    glm::dvec2 where{0.0};
};
std::optional<Crossing> find_crossing(const std::vector<std::vector<glm::dvec2>>& loops);

} // namespace isoparm::geom
