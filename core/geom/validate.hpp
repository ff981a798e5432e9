// Whole-object validation: degree, counts, knots, weights and the type's own rules.
#pragma once

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

constexpr int max_points_per_direction = 4096;
constexpr long max_points_per_surface = 1000000;
constexpr long max_evaluation_points = 10000000;

// Paths are relative to the object: "/degree", "/knots/5", "/knots/0/3" (surface u),
// "/weights/2", "/points". Checks: degree >= 1 (`degree`), n >= p + 1 (`degree`), the knot
// vector (`knots`), finite weights of the right count (`weights`), unit weights for
// non-rational types (`weights`), a single span for Bezier types (`knots`).
Status validate_curve(const Curve& c);
Status validate_surface(const Surface& s);

} // namespace isoparm::geom
