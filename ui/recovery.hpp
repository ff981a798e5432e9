// Crash recovery in the window: the start-up dialog that offers autosaved work back, and
// restoring it as unsaved changes of the scene it came from.
#pragma once

#include "core/scene/autosave.hpp"
#include "ui/app_context.hpp"

namespace isoparm::ui {

// The modal "Restore unsaved work?" dialog for ctx.ui.recovery.offers[0], shown once no other
// dialog is up. Restore: restore_recovery (the other offers wait for the next start). Discard:
// the recovery file is removed and the next offer, if any, is asked about. Decide later (Esc):
// every offer stays on disk for the next start, and this session does not autosave over them.
void draw_recovery_dialog(AppContext& ctx);

// Loads the recovery file as unsaved changes of its scene: the document starts as the scene file
// saved on disk (a new document when untitled or unreadable), keeps its path, and the recovered
// document is applied as one undoable command ("Restore unsaved changes": the title shows '*',
// Undo returns to the saved file). A recovery file that does not load shows the error dialog
// and changes nothing. Returns whether it was restored.
bool restore_recovery(AppContext& ctx, const scene::RecoveryInfo& recovery);

} // namespace isoparm::ui
