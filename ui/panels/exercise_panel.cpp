// The Exercise panel: the task, Check (every check of the exercise on the document as it is,
// each passed or failed with what was found, and the hint for the first that fails), the
// exercise's general hints one at a time, Start again and Close.
#include <algorithm>
#include <cmath>
#include <imgui.h>
#include <string>

#include "ui/course_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/rich_text.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/caption_place.hpp"

namespace isoparm::ui {

void draw_exercise_panel(AppContext& ctx) {
    ExerciseState& s = ctx.ui.course.exercise;
    if (!ctx.ui.course.exercise_open || !s.exercise) return;
    const scene::Exercise& ex = *s.exercise;
    const float k = ctx.ui.scale();
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const Rect& view = ctx.ui.drawing_rect;
    const float width = std::max(std::min(440 * k, view.w - 16 * k), 260 * k);
    // Off the scene's objects where the view has room (ui/view/caption_place.hpp), placed
    // again when the results change its height, until the user drags it elsewhere.
    const float height = s.last_height > 0 ? s.last_height : 180 * k;
    if (!s.user_moved && (!s.placed_once || std::abs(height - s.placed.h) > 2)) {
        const Rect& area = ctx.ui.view_rect.w > 0 ? ctx.ui.view_rect : view;
        CaptionFocus focus = caption_focus(ctx.doc, ctx.ui.camera, area, 14 * k);
        focus.points.clear(); // a student works on the points: the panel need not dodge them
        const Rect r =
            place_caption(area, width, height, focus, 8 * k, s.placed_once ? &s.placed : nullptr);
        ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + r.x, vp->Pos.y + r.y), ImGuiCond_Always);
        s.placed = r;
        s.placed_once = true;
    }
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, vp->Size.y * 0.7f));
    bool open = true;
    const std::string title = "Exercise: " + (ex.title.empty() ? s.path : ex.title) + "###exercise";
    if (ImGui::Begin(title.c_str(), &open,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
        const ImVec2 wp = ImGui::GetWindowPos(), ws = ImGui::GetWindowSize();
        report_rect("exercise/window", wp.x, wp.y, ws.x, ws.y);
        s.last_height = ws.y;
        if (std::abs(wp.x - vp->Pos.x - s.placed.x) > 0.5f ||
            std::abs(wp.y - vp->Pos.y - s.placed.y) > 0.5f)
            s.user_moved = true; // dragged by its title bar
        ctx.ui.course.floating.push_back({wp.x - vp->Pos.x, wp.y - vp->Pos.y, ws.x, ws.y});
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
