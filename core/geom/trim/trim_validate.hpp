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
// then between loops: no two cross or overlap along a piece (`geometry`, both loops and the
// point), each hole inside the outer loop and outside every other hole (`geometry`). Two loops
// may touch at isolated points (a vertex of one on the other, within trim_touch: a hole whose
// start is on the outer loop, as ec_turbine-A.stp's face 1 has): there every point of the two
// loops away from the touching points decides the nesting, so a loop that touches another and
// goes on to its wrong side is refused as lying outside (or inside) it.
Status validate_trim(const Trim& trim, const ParamRect& domain);

// Fraction of the domain's larger side within which two loops meeting at a vertex of either
// touch there (rather than cross).
constexpr double trim_touch = 1e-9;

// Where two of the polylines' chords meet, for validation and its tests: the first crossing
// or touching of two segments that are not neighbours on the same loop (a segment's
// neighbours share its ends). loops[k] is closed (last point back to the first). With
// `touches`, two segments of different loops that meet within `touch` of an end of either and
// do not overlap along a piece longer than `touch` are a touch: listed there, not returned.
struct Crossing {
    int loop_a = 0, segment_a = 0, loop_b = 0, segment_b = 0;
    glm::dvec2 where{0.0};
};
std::optional<Crossing> find_crossing(const std::vector<std::vector<glm::dvec2>>& loops,
                                      double touch = 0, std::vector<Crossing>* touches = nullptr);

} // namespace isoparm::geom
