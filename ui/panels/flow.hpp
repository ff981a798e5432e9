// Rows of controls that wrap in a narrow column (a projector in presentation mode) instead of
// being cut at the panel's edge.
#pragma once

#include <imgui.h>

namespace isoparm::ui {

// The width a checkbox or radio button with this label takes.
inline float toggle_width(const char* label) {
    return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
           ImGui::CalcTextSize(label, nullptr, true).x;
}
// The width a button with this label takes.
inline float button_width(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetStyle().FramePadding.x * 2;
}
// How many columns of items `width` wide fit the rest of the row (at least 1, at most `most`).
inline int columns_that_fit(float width, int most) {
    const int n = static_cast<int>(ImGui::GetContentRegionAvail().x / (width > 1 ? width : 1));
    return n < 1 ? 1 : n > most ? most : n;
}
// Continues the row when `width` more pixels fit on it, else starts the next line.
inline void same_line_if_fits(float width) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

} // namespace isoparm::ui
