// The command that replaces the whole document by one restored from a recovery file, so the
// restored work shows as unsaved changes and Undo returns to the scene as it was saved.
#pragma once

#include <memory>

#include "core/doc/command.hpp"

namespace isoparm::doc {

// "Restore unsaved changes": the document becomes `recovered` (already loaded and validated
// by load_scene); revert gives back the document it replaced, bit for bit.
std::unique_ptr<Command> restore_document(Document recovered);

} // namespace isoparm::doc
