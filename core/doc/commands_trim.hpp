// Trimming a surface: its trim loops set, replaced or removed, one undo step each.
#pragma once

#include <memory>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"

namespace isoparm::doc {

// The surface's trim becomes `trim` (validate_trim against its domain: errors under "/trim",
// "/trim/holes/1/0", naming the loop and the problem); an empty trim removes it. A surface
// only (`schema` at "/id" for another kind).
std::unique_ptr<Command> set_trim(std::uint64_t id, geom::Trim trim);
// set_trim with no loops: the whole domain again.
std::unique_ptr<Command> remove_trim(std::uint64_t id);

} // namespace isoparm::doc
