// A canvas's help tooltip ("drag a point to move it ..."), shown once the pointer has rested on
// the canvas for a moment instead of at once, as ImGui 1.86 shows every tooltip: on a projector
// a hint at the cursor the moment a drag ends covers the labels under it (the dragged point's
// own). Live readouts (the value under the pointer) stay immediate; this is for help text.
#pragma once

#include "ui/ui_state.hpp"

namespace isoparm::ui {

// Seconds the pointer must rest (not move, no button held) on the canvas before its hint.
constexpr double canvas_hint_delay = 0.6;

// Whether the last item's hint is due now. Until it shows it sets ui.hint_waiting, and the
// workstation asks for frames, so the hint appears without another input.
bool canvas_hint_due(UiState& ui);

} // namespace isoparm::ui
