// The stage button, the hovered teaching view and staged canvases' zoom and pan.
#include "ui/panels/stage_controls.hpp"

#include <algorithm>
#include <cmath>
#include <imgui.h>

#include "ui/ui_report.hpp"

namespace isoparm::ui {

bool on_stage(const AppContext& ctx, StageView v) {
    return v != StageView::none && ctx.ui.stage.view == v;
}

void set_stage(AppContext& ctx, StageView v) {
    StageState& st = ctx.ui.stage;
    st.view = v;
    st.four_views = false;
    st.panning.clear();
}

void set_four_views(AppContext& ctx, bool on) {
    StageState& st = ctx.ui.stage;
    st.four_views = on;
    st.view = StageView::none;
    st.panning.clear();
}

void stage_button(AppContext& ctx, StageView v, bool same_line) {
    const StageViewInfo* info = stage_info(v);
    if (!info) return;
    const float size = ImGui::GetFrameHeight();
    if (same_line) {
        const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
        ImGui::SameLine();
        const float x = std::max(ImGui::GetCursorScreenPos().x, right - size);
        ImGui::SetCursorScreenPos(ImVec2(x, ImGui::GetCursorScreenPos().y));
    }
    ImGui::PushID(info->name);
    const bool pressed = ImGui::InvisibleButton("##stage", ImVec2(size, size));
    ImGui::PopID();
    report_item(std::string("stage_button/") + info->name);
    const bool staged = on_stage(ctx, v);
    const bool hot = ImGui::IsItemHovered();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    dl->AddRectFilled(a, b,
                      ImGui::GetColorU32(ImGui::IsItemActive() ? ImGuiCol_ButtonActive
                                         : hot                 ? ImGuiCol_ButtonHovered
                                                               : ImGuiCol_Button),
                      ImGui::GetStyle().FrameRounding);
    // Four corner marks pointing out (expand) or in (back), as players draw full screen.
    const ImU32 col = ImGui::GetColorU32(ImGuiCol_Text);
    const float k = size * 0.22f, len = size * 0.2f, w = std::max(1.f, size / 14);
    const ImVec2 c[4] = {ImVec2(a.x + k, a.y + k), ImVec2(b.x - k, a.y + k),
                         ImVec2(a.x + k, b.y - k), ImVec2(b.x - k, b.y - k)};
    for (int q = 0; q < 4; ++q) {
        const float sx = (q & 1) ? -1.f : 1.f, sy = (q & 2) ? -1.f : 1.f;
        const ImVec2 p = staged ? ImVec2(c[q].x + sx * len, c[q].y + sy * len) : c[q];
        const float dx = staged ? -sx : sx, dy = staged ? -sy : sy;
        dl->AddLine(p, ImVec2(p.x + dx * len, p.y), col, w);
        dl->AddLine(p, ImVec2(p.x, p.y + dy * len), col, w);
    }
    if (hot)
        ImGui::SetTooltip(staged ? "Back to the workstation (Esc or T)"
                                 : "Show %s at full size (T over the view, or View > Stage)",
                          info->title);
    if (pressed) set_stage(ctx, staged ? StageView::none : v);
}

void note_hovered_view(AppContext& ctx, StageView v) {
    if (ImGui::IsWindowHovered(ImGuiHoveredFlags_ChildWindows |
                               ImGuiHoveredFlags_AllowWhenBlockedByActiveItem))
        ctx.ui.stage.hovered_next = v;
}

CanvasView canvas_view(AppContext& ctx, const std::string& name, const Rect& canvas) {
    StageState& st = ctx.ui.stage;
    if (!st.active()) return {};
    CanvasView& v = st.canvases[name];
    if (st.fit) v = {};
    const ImGuiIO& io = ImGui::GetIO();
    const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenBlockedByActiveItem)) {
        if (io.MouseWheel != 0) zoom_at(v, canvas, mouse, std::pow(1.15, io.MouseWheel));
        if (ImGui::IsMouseClicked(ImGuiMouseButton_Right) ||
            ImGui::IsMouseClicked(ImGuiMouseButton_Middle))
            st.panning = name;
    }
    if (st.panning == name) {
        if (ImGui::IsMouseDown(ImGuiMouseButton_Right) ||
            ImGui::IsMouseDown(ImGuiMouseButton_Middle))
            v.pan += glm::dvec2(io.MouseDelta.x, io.MouseDelta.y);
        else
            st.panning.clear();
    }
    report_fact("stage/zoom/" + name, v.zoom);
    return v;
}

} // namespace isoparm::ui
