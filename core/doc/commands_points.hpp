// Many control points of one object moved at once: a selection dragged by its handle, moved,
// turned, scaled or mirrored by typed values, a symmetric edit's point and its mirror partner
// (docs/commands.md: move_points, transform_points).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"

namespace isoparm::doc {

// Refusals: "/id" (no such object, an implicit surface), "/points" (none, or too many),
// "/points/k" (outside the net, or named twice), "/positions" (not one per point),
// "/positions/k/a" (not finite), "/matrix" (not finite or not affine, or a point sent to
// infinity), "/about" (not finite). A curve in chord-length or centripetal knot mode gets the
// knots of its new polygon, a closed curve stays closed (a repeated point moves with its
// original), and a subpatch's neighbours follow under the continuity setting, as for one point.

// The points go to `positions` (one each, in order). Consecutive moves of the same points of
// the same object merge into one undo step (a drag of the selection's handle); the spec is
// then the final positions.
std::unique_ptr<Command> move_points(MovePointsSpec spec);
// The points are mapped by `matrix` (affine), about the selection's centroid, a given point or
// the origin: scale a row by 2 about its centroid, mirror a selection in a plane through a
// point, turn it. Each is its own undo step (typed values; a drag is move_points).
std::unique_ptr<Command> transform_points(TransformPointsSpec spec);

} // namespace isoparm::doc
