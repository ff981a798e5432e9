// File > Export... and File > Import...: the file dialog in its export and import modes, and
// what its button does (core/scene/export_document.hpp, import_document.hpp).
#pragma once

#include <string>

#include "ui/app_context.hpp"

namespace isoparm::ui {

// The file dialog asking where to export (the scene's name with .step) / what to import.
void request_export_dialog(AppContext& ctx);
void request_import_dialog(AppContext& ctx);

// Every visible object in the format of `path`'s extension (as `isoparm export` writes it:
// 32 samples per direction for meshes), written atomically and never over the scene's own
// file. A refusal or a failed write fills `error` (for the dialog) and writes nothing; what
// was skipped goes to the status bar.
bool export_visible_objects(AppContext& ctx, const std::string& path, std::string& error);

// The curves and surfaces of an IGES, STEP or OBJ file added to the document as ONE undoable
// step (doc::add_objects), the first one selected and the view fitted. A file that does not
// import fills `error` and changes nothing; what was skipped goes to the status bar.
bool import_objects(AppContext& ctx, const std::string& path, std::string& error);

// Whether the file dialog lists this file in its export / import mode (the formats' extensions).
bool is_exchange_file(const std::string& name);

} // namespace isoparm::ui
