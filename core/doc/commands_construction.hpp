// Constructions as commands: build an object that stays linked to its inputs, change its
// recipe, or detach it (docs/commands.md: construct, edit_construction, detach).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/doc/command.hpp"
#include "core/doc/recipe.hpp"

namespace isoparm::doc {

// Refusals name the value at fault under "/construction" as the JSON form writes the recipe:
// "/construction/inputs" (the count), "/construction/inputs/k" (no such object, the wrong kind,
// a cycle, or the geometry's complaint about that input: "/construction/inputs/1/points/3"),
// "/construction/angle", "/construction/scale", "/construction/degree",
// "/construction/sections", "/construction/gordon_u_count", "/construction/param",
// "/construction/refinements/k"; "/name" for a bad name, "/id" for the object.

// A new object built by the recipe (build_construction, refinements included), keeping the
// recipe: a later edit of an input rebuilds it. name: empty for the construction's own
// ("revolve profile"). The object is added last and gets the next free id (a redo keeps it).
std::unique_ptr<Command> construct(Recipe recipe, std::string name = {});
// The constructed object's recipe becomes `recipe` (operation, inputs and parameters; the
// refinements recorded on it are kept and repeated) and its shape the new recipe's result;
// the output must be the same kind of object, and the inputs must not read the object (a
// cycle). Consecutive edits of one object merge into one undo step (a slider in the dialog).
std::unique_ptr<Command> edit_construction(std::uint64_t id, Recipe recipe);
// The object keeps its shape and forgets its recipe: a free object from now on.
std::unique_ptr<Command> detach(std::uint64_t id);

// What an applied construct or edit_construction command said about its result (the skin's
// parameters, the oriented sweep's deviation), and the id of the object construct made (0 for
// any other command). Either may be given the history's top command.
std::string construction_note(const Command& command);
std::uint64_t constructed_id(const Command& command);

} // namespace isoparm::doc
