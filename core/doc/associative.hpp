// Constructions stay linked to their inputs (Ayam's tool objects, Rhino's history): every
// command the history runs goes through `associative`, which rebuilds, inside that same
// command, each constructed object whose inputs it changed (in dependency order, so a chain
// profile -> vase -> isocurve -> collar follows), and refuses an edit of a constructed object's
// own points (detach it first) and a recipe that would read itself. Undo takes the edit and
// every rebuild back at once. No observers, no callbacks: the recipe is data on the object
// (Object::construction) and the rebuild is the recipe run again (build_construction).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/doc/command.hpp"
#include "core/doc/document.hpp"

namespace isoparm::doc {

// The command with its dependants kept: what History::execute and Command::check run. Wrapping
// twice gives the same wrapper. spec(), label() (with " (rebuilds vase)" where it rebuilt) and
// merging (a drag of a profile point is one undo step with its rebuilds) answer as the inner
// command does.
std::unique_ptr<Command> associative(std::unique_ptr<Command> inner);
// The command inside an associative wrapper (or the command itself).
const Command& unwrapped(const Command& command);

// The constructed object whose own shape the command `spec` would change on `doc` (not by a
// refinement the recipe records): the edit `associative` refuses until that object is detached.
// The window asks to detach it and then runs the command; `label` is what the command would
// say it did (some labels are only known once applied). Nothing when the command edits no
// constructed object or is refused for another reason.
struct ConstructedEdit {
    std::uint64_t object = 0;
    std::string label;
};
std::optional<ConstructedEdit> constructed_object_edited(const Document& doc,
                                                         const CommandSpec& spec);

// The constructed objects that read any of `changed`, directly or through other constructed
// objects, each after every constructed object it reads (the order to rebuild them in).
std::vector<std::uint64_t> dependants_in_order(const Document& doc,
                                               const std::vector<std::uint64_t>& changed);
// Whether object `reader` reads object `id` through its recipe, directly or through others.
bool reads(const Document& doc, std::uint64_t reader, std::uint64_t id);

// The links of object `id`'s recipe `recipe` in `doc`: every input exists and is of the kind
// the construction takes (isocurve: a surface; the others: curves), none is `id` itself or reads
// it (a cycle), and the output is the kind the object is. Errors at "/construction/inputs/k"
// ("/construction/operation" for the output kind), naming the objects: "'vase' cannot read
// 'rim': 'rim' is built from 'vase'".
geom::Status check_recipe_links(const Document& doc, std::uint64_t id, const Object& object,
                                const Recipe& recipe);

// The shape object's recipe builds from the document as it is now (build_construction).
geom::Expected<Shape> rebuilt_shape(const Document& doc, const Object& object);

// Rebuilds every constructed object that reads `changed`, in order, without a command (the
// animation's preview of a weight or knot); returns each replaced (id, shape) so the caller
// can put them back (restore_shapes, in reverse). On a refusal nothing is left changed.
struct ReplacedShape {
    std::uint64_t id = 0;
    Shape before;
};
geom::Expected<std::vector<ReplacedShape>>
rebuild_dependants(Document& doc, const std::vector<std::uint64_t>& changed);
void restore_shapes(Document& doc, std::vector<ReplacedShape>& replaced);

} // namespace isoparm::doc
