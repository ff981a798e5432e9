// The Exercise panel: the task, Check (every check of the exercise on the document as it is,
// each passed or failed with what was found, and the hint for the first that fails), the
// exercise's general hints one at a time, Start again and Close.
#include <algorithm>
#include <imgui.h>
#include <string>

#include "ui/course_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/rich_text.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"

namespace isoparm::ui {

void draw_exercise_panel(AppContext& ctx) {
    ExerciseState& s = ctx.ui.course.exercise;
    if (!ctx.ui.course.exercise_open || !s.exercise) return;
    const scene::Exercise& ex = *s.exercise;
    const float k = ctx.ui.scale();
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const Rect& view = ctx.ui.drawing_rect;
    const float width = std::max(std::min(440 * k, view.w - 16 * k), 260 * k);
    // At the bottom left of the 3D view, where a lesson's caption box rarely goes.
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + view.x + 8 * k, vp->Pos.y + view.y + view.h - 8 * k),
                            ImGuiCond_Appearing, ImVec2(0, 1));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, vp->Size.y * 0.7f));
    bool open = true;
    const std::string title = "Exercise: " + (ex.title.empty() ? s.path : ex.title) + "###exercise";
    if (ImGui::Begin(title.c_str(), &open,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
        const ImVec2 wp = ImGui::GetWindowPos(), ws = ImGui::GetWindowSize();
        report_rect("exercise/window", wp.x, wp.y, ws.x, ws.y);
        draw_rich_text(ex.task);
        ImGui::Spacing();
        const bool check = ImGui::Button("Check");
        report_item("exercise/check");
        ImGui::SameLine();
        ImGui::BeginDisabled(s.hints_shown >= static_cast<int>(ex.hints.size()));
        if (ImGui::Button(s.hints_shown == 0 ? "A hint" : "Another hint")) ++s.hints_shown;
        ImGui::EndDisabled();
        ImGui::SameLine();
        const bool again = ImGui::Button("Start again");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("The exercise's starting scene, afresh");
        ImGui::SameLine();
        if (ImGui::Button("Close")) open = false;
        ImGui::PushTextWrapPos(0);
        for (int h = 0; h < s.hints_shown && h < static_cast<int>(ex.hints.size()); ++h)
            ImGui::TextDisabled("Hint %d: %s", h + 1,
                                ex.hints[static_cast<std::size_t>(h)].c_str());
        if (s.grade) {
            ImGui::Separator();
            const scene::Grade& g = *s.grade;
            const bool stale = ctx.history.size() != s.history_at_check ||
                               static_cast<const void*>(ctx.history.top()) != s.top_at_check;
            if (g.passed())
                ImGui::TextColored(ImVec4(0.35f, 0.85f, 0.45f, 1),
                                   "All %zu checks pass. Well done!", g.checks.size());
            else
                ImGui::Text("%zu of %zu checks pass.", g.passed_count(), g.checks.size());
            report_fact("exercise/passed", static_cast<double>(g.passed_count()));
            report_fact("exercise/checks", static_cast<double>(g.checks.size()));
            const scene::CheckResult* first = g.first_failure();
            for (const scene::CheckResult& c : g.checks) {
                const ImVec4 colour =
                    c.passed ? ImVec4(0.35f, 0.85f, 0.45f, 1) : error_text_color();
                ImGui::TextColored(colour, "%s %s", c.passed ? "[ok]" : "[no]", c.label.c_str());
                if (!c.passed) {
                    ImGui::Indent();
                    ImGui::TextUnformatted(c.message.c_str());
                    if (&c == first && !c.hint.empty())
                        ImGui::TextColored(ImGui::GetStyleColorVec4(ImGuiCol_PlotHistogram),
                                           "Hint: %s", c.hint.c_str());
                    ImGui::Unindent();
                }
            }
            if (stale) ImGui::TextDisabled("(checked before your last change: Check again)");
        }
        ImGui::PopTextWrapPos();
        if (check) check_exercise(ctx);
        if (again) {
            const std::string path = s.path;
            request_open_exercise(ctx, path);
        }
    }
    ImGui::End();
    if (!open) close_exercise(ctx);
}

} // namespace isoparm::ui
