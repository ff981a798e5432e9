// Multiresolution editing as a document command (geom/multires_edit.hpp; Finkelstein &
// Salesin 1994): move a coarse control point keeping the detail, or scale the detail keeping
// the coarse points. One edit (a whole drag) is one undo step.
#pragma once

#include <memory>
#include <utility>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"

namespace isoparm::doc {

// The finest levels (J_u, J_v) of an object that has levels (curves: J_v = -1). Refusals name
// the offending value: geom::multires_level's paths ("/weights/k", "/degree", "/points",
// "/knots/k"; surfaces "/n_u", "/knots_v/k", ...), an implicit surface or a curve whose knots
// follow its polygon (chord length, centripetal, closed) at "/id". The menus grey their item
// with this message.
geom::Expected<std::pair<int, int>> multires_levels_of(const Object& object);

// spec.position: coarse point i (surfaces: i, j) at `level` (surfaces: level along u,
// level_v along v) moves there, every detail coefficient kept; consecutive moves of the same
// coarse point at the same levels merge (a drag). spec.detail_scale: every detail coefficient
// finer than the level is multiplied by it, the coarse points kept. Exactly one of the two
// ("/position" when neither, "/detail_scale" when both); curves take neither j nor level_v
// ("/j", "/level_v"), surfaces need level_v ("/level_v").
std::unique_ptr<Command> multires_edit(MultiresEditSpec spec);

} // namespace isoparm::doc
