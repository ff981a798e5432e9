// Files from the user's computer in the browser build (ui/platform/files.hpp): the file
// dialog's "From this computer..." button asks the browser's picker for one, and each frame
// hands what arrived to the action it was chosen for, as if its path had been chosen in the
// dialog. On the desktop nothing ever arrives.
#pragma once

#include "ui/app_context.hpp"

namespace isoparm::ui {

// The browser's picker for what the file dialog in `mode` opens (a scene, a lesson, an exchange
// file, data points); false for the modes that write (they download instead).
bool request_upload_for(FileDialog::Mode mode);

// Opens, imports or loads the files that arrived since the last frame.
void receive_uploads(AppContext& ctx);

} // namespace isoparm::ui
