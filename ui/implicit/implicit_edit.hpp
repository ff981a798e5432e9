// The undoable edit of an implicit object: replace_shape, with consecutive edits of the same
// object and label merging into one undo step (a parameter slider drag).
#pragma once

#include <memory>
#include <string>

#include "core/doc/command.hpp"

namespace isoparm::ui {

// Validation and refusals are replace_shape's ("/id", "/shape/..."); an object that is not
// implicit is refused with `schema` at "/id". Merges with the next edit_implicit of the same
// id and label until the history is sealed.
std::unique_ptr<doc::Command> edit_implicit(std::uint64_t id, doc::ImplicitObject shape,
                                            std::string label);

} // namespace isoparm::ui
