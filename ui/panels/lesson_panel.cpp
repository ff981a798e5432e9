// The lesson bar over the 3D view: the caption, where the lesson stands, and Next (Right arrow
// or Page Down), Restart and Close.
#include <algorithm>
#include <filesystem>
#include <imgui.h>
#include <string>

#include "ui/actions.hpp"
#include "ui/lesson.hpp"
#include "ui/panels/panels.hpp"
#include "ui/ui_report.hpp"

namespace isoparm::ui {

void draw_lesson_panel(AppContext& ctx) {
    if (!ctx.ui.lesson) return;
    Lesson& lesson = *ctx.ui.lesson;
    const float k = ctx.ui.scale();
    // Over the top of the 3D view, inside it, where the class looks anyway.
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const Rect& view = ctx.ui.drawing_rect;
    const float width = std::max(std::min(560 * k, view.w - 16 * k), 240 * k);
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + view.x + view.w * 0.5f, vp->Pos.y + view.y + 34 * k),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, vp->Size.y * 0.5f));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing;
    bool open = true;
    const std::string title =
        "Lesson: " + std::filesystem::path(lesson.path).filename().string() + "###lesson";
    if (ImGui::Begin(title.c_str(), &open, flags)) {
        ImGui::PushTextWrapPos(0);
        ImGui::TextUnformatted(lesson.caption.empty() ? "(no caption yet)"
                                                      : lesson.caption.c_str());
        ImGui::PopTextWrapPos();
        for (const std::string& u : lesson.unmet)
            ImGui::TextColored(ImVec4(1, 0.72f, 0.3f, 1), "Not as the lesson expected: %s",
                               u.c_str());
        if (!lesson.refused.empty())
            ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "This step could not be done: %s",
                               lesson.refused.c_str());
        ImGui::TextDisabled("Stop %zu of %zu, step %zu of %zu", lesson.pauses_done(),
                            lesson.pauses(), lesson.next, lesson.script.steps.size());
        const bool can_go_on = !lesson.finished() && lesson.refused.empty();
        ImGui::BeginDisabled(!can_go_on);
        bool next = ImGui::Button(lesson.finished() ? "The end" : "Next  >");
        report_item("lesson/next");
        ImGui::EndDisabled();
        ImGui::SameLine();
        if (ImGui::Button("Restart")) restart_lesson(ctx);
        ImGui::SameLine();
        if (ImGui::Button("Close")) open = false;
        // Right arrow or Page Down: the next stop, as a presenter's clicker sends.
        if (can_go_on && !ImGui::GetIO().WantTextInput &&
            (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow), false) ||
             ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageDown), false)))
            next = true;
        if (next && can_go_on) lesson_next(ctx);
    }
    ImGui::End();
    if (!open) ctx.ui.lesson.reset();
}

} // namespace isoparm::ui
