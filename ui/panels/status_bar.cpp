// The status bar: frame time, current object and point, unsaved mark, last message.
#include <cstdio>
#include <imgui.h>
#include <string>

#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/render/renderer.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

float status_bar_height() {
    return ImGui::GetFrameHeight();
}

void draw_status_bar(AppContext& ctx) {
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const float h = status_bar_height();
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x, vp->Pos.y + vp->Size.y - h));
    ImGui::SetNextWindowSize(ImVec2(vp->Size.x, h));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding,
                        ImVec2(8 * ctx.ui.scale(), 3 * ctx.ui.scale()));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 0);
    const ImGuiWindowFlags flags =
        ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
        ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoScrollbar;
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImGui::GetStyleColorVec4(ImGuiCol_MenuBarBg));
    if (ImGui::Begin("##status", nullptr, flags)) {
        // Headless frames show no timings, so renders are reproducible.
        if (ctx.ui.headless)
            ImGui::TextUnformatted("frame --");
        else
            ImGui::Text("frame %5.1f ms", ctx.ui.frame_ms);
        if (ctx.renderer && !ctx.ui.headless && ctx.renderer->stats().retessellated > 0) {
            ImGui::SameLine();
            ImGui::TextDisabled("(tessellate %.2f ms)", ctx.renderer->stats().tessellate_ms);
        }
        if (ctx.recorder) {
            ImGui::SameLine(0, 24 * ctx.ui.scale());
            ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1), "REC %zu steps",
                               ctx.recorder->step_count());
        }
        ImGui::SameLine(0, 24 * ctx.ui.scale());
        // The selected object, whatever its kind (never another one).
        ImGui::TextUnformatted(selection_summary(ctx).c_str());
        // Many selected points: how many and where their centroid is.
        if (const std::string many = points_selection_summary(ctx); !many.empty()) {
            ImGui::SameLine(0, 16 * ctx.ui.scale());
            ImGui::TextUnformatted(many.c_str());
            report_item("status/selection");
        }
        ImGui::SameLine(0, 24 * ctx.ui.scale());
        if (ctx.dirty())
            ImGui::TextUnformatted("* unsaved changes");
        else
            ImGui::TextDisabled("saved");
        // A message is news for a while, then fades and goes: an old refusal must not read
        // as the answer to the next action.
        StatusAge& age = ctx.ui.status_age;
        const double now = ImGui::GetTime();
        if (ctx.ui.status != age.text) {
            age.text = ctx.ui.status;
            age.since = now;
        }
        const double shown_for = now - age.since;
        if (!ctx.ui.status.empty() && shown_for < status_seconds) {
            ImGui::SameLine(0, 24 * ctx.ui.scale());
            const float fade = shown_for < status_seconds - 2 ? 1.f : 0.45f;
            ImGui::PushStyleVar(ImGuiStyleVar_Alpha, fade);
            ImGui::TextUnformatted(ctx.ui.status.c_str());
            ImGui::PopStyleVar();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", ctx.ui.status.c_str());
        }
    }
    ImGui::End();
    ImGui::PopStyleColor();
    ImGui::PopStyleVar(2);
}

} // namespace isoparm::ui
