// A row of tabs that wraps onto further rows in a narrow column instead of shortening the
// names (ImGui's tab bar shows "Hom..." on a projector): each name stays whole and readable.
#pragma once

#include <vector>

namespace isoparm::ui {

struct TabLabel {
    const char* name; // also the UI report's "tab/NAME"
    const char* what; // the tooltip
};

// Draws the strip and a separator under it; returns the selected index (current, or the tab
// clicked this frame), always within [0, tabs.size()). The first row leaves `reserve` pixels
// free at its right end (for a button drawn there).
int tab_strip(const std::vector<TabLabel>& tabs, int current, float reserve = 0);

} // namespace isoparm::ui
