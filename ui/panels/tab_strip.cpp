// The wrapping tab strip (see the header): buttons in the theme's tab colours.
#include "ui/panels/tab_strip.hpp"

#include <algorithm>
#include <imgui.h>
#include <string>

#include "ui/ui_report.hpp"

namespace isoparm::ui {

int tab_strip(const std::vector<TabLabel>& tabs, int current, float reserve) {
    if (tabs.empty()) return 0;
    int selected = std::clamp(current, 0, static_cast<int>(tabs.size()) - 1);
    const ImGuiStyle& st = ImGui::GetStyle();
    ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing,
                        ImVec2(st.ItemInnerSpacing.x, st.ItemInnerSpacing.y));
    ImGui::PushStyleVar(ImGuiStyleVar_FrameRounding, st.TabRounding);
    const int shown = selected;
    const float first_row_y = ImGui::GetCursorScreenPos().y;
    for (int k = 0; k < static_cast<int>(tabs.size()); ++k) {
        const TabLabel& t = tabs[static_cast<std::size_t>(k)];
        if (k > 0) {
            ImGui::SameLine();
            const bool first_row = ImGui::GetCursorScreenPos().y == first_row_y;
            if (ImGui::GetContentRegionAvail().x - (first_row ? reserve : 0.f) <
                ImGui::CalcTextSize(t.name).x + st.FramePadding.x * 2)
                ImGui::NewLine();
        }
        const bool on = k == shown;
        ImGui::PushStyleColor(ImGuiCol_Button,
                              ImGui::GetStyleColorVec4(on ? ImGuiCol_TabActive : ImGuiCol_Tab));
        ImGui::PushStyleColor(ImGuiCol_ButtonHovered,
                              ImGui::GetStyleColorVec4(ImGuiCol_TabHovered));
        ImGui::PushStyleColor(ImGuiCol_ButtonActive, ImGui::GetStyleColorVec4(ImGuiCol_TabActive));
        if (ImGui::Button(t.name)) selected = k;
        ImGui::PopStyleColor(3);
        report_item(std::string("tab/") + t.name);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s", t.name, t.what);
    }
    ImGui::PopStyleVar(2);
    ImGui::Separator();
    return selected;
}

} // namespace isoparm::ui
