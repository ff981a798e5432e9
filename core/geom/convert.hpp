// Changing an object's spline type (Surface > Convert to, the `convert` op).
#pragma once

#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The object as `to`, shape unchanged: one piece, or, for a Bezier type and an object of
// several spans (or unclamped ends), its Bezier pieces (split at every distinct interior knot
// after clamping; surfaces in u-major order: all v-pieces of the first u-strip first), each on
// its own part of the original domain. A rational object becomes a non-rational type only
// when all its weights are equal (`weights` at "/weights/k", the first that differs, or
// "/weights/i/j" for a surface); then every weight becomes 1.
Expected<std::vector<Curve>> convert(const Curve& c, SplineType to);
Expected<std::vector<Surface>> convert(const Surface& s, SplineType to);

} // namespace isoparm::geom
