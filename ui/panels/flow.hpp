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
// Continues the row when `width` more pixels fit on it, else starts the next line.
inline void same_line_if_fits(float width) {
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

} // namespace isoparm::ui
