// The lesson editor: a lesson's title and summary (what the Lessons menu shows), its stops
// with their captions, in order; a stop's caption edited (several lines, **bold**), stops
// moved and deleted, the lesson played from any stop, and saved in the script format.
#include <algorithm>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <string>

#include "ui/course_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"

namespace isoparm::ui {

namespace {

std::string first_line(const std::string& s) {
    const std::string line = s.substr(0, s.find('\n'));
    return line.size() > 60 ? line.substr(0, 57) + "..." : line;
}

void changed(LessonEditorState& e) {
    e.dirty = true;
    e.problem = draft_problem(e);
}

} // namespace

void draw_lesson_editor_panel(AppContext& ctx) {
    LessonEditorState& e = ctx.ui.course.editor;
    if (!e.open || !e.draft) return;
    scene::LessonDraft& d = *e.draft;
    const float k = ctx.ui.scale();
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + 12 * k, vp->Pos.y + 40 * k), ImGuiCond_Appearing);
    ImGui::SetNextWindowSize(
        ImVec2(std::min(460 * k, vp->Size.x * 0.6f), std::min(560 * k, vp->Size.y * 0.85f)),
        ImGuiCond_Appearing);
    bool open = true;
    const std::string title = std::string("Lesson editor") + (e.dirty ? " *" : "") + "###editor";
    if (!ImGui::Begin(title.c_str(), &open, ImGuiWindowFlags_NoCollapse)) {
        ImGui::End();
        if (!open) e.open = false;
        return;
    }
    const ImVec2 wp = ImGui::GetWindowPos(), ws = ImGui::GetWindowSize();
    report_rect("editor/window", wp.x, wp.y, ws.x, ws.y);
    ctx.ui.course.floating.push_back({wp.x - vp->Pos.x, wp.y - vp->Pos.y, ws.x, ws.y});
    ImGui::TextDisabled("%s", e.path.empty() ? "not saved yet" : e.path.c_str());
    ImGui::SetNextItemWidth(-80 * k);
    if (ImGui::InputText("Title", &d.title)) e.dirty = true;
    report_item("editor/title");
    ImGui::SetNextItemWidth(-80 * k);
    if (ImGui::InputText("Summary", &d.summary)) e.dirty = true;
    report_item("editor/summary");
    if (d.summary.size() > 60)
        ImGui::TextColored(error_text_color(),
                           "The menu shows one line: keep it under 60 letters.");

    ImGui::Text("Stops (%zu)", d.size());
    e.selected = std::clamp(e.selected, 0, static_cast<int>(d.size()) - 1);
    const float list_h = ImGui::GetTextLineHeightWithSpacing() * 7;
    if (ImGui::BeginChild("##stops", ImVec2(0, list_h), true)) {
        for (std::size_t s = 0; s < d.size(); ++s) {
            const std::string cap = d.caption(s);
            const std::string label =
                std::to_string(s + 1) + ". " + (cap.empty() ? "(no caption)" : first_line(cap)) +
                "  [" + std::to_string(d.actions(s)) + " steps]" +
                (d.stops[s].paused ? "" : "  (the end)") + "##stop" + std::to_string(s);
            if (ImGui::Selectable(label.c_str(), static_cast<int>(s) == e.selected))
                e.selected = static_cast<int>(s);
            report_item("editor/stop" + std::to_string(s));
        }
    }
    ImGui::EndChild();

    const auto sel = static_cast<std::size_t>(e.selected);
    if (e.caption_of != e.selected) {
        e.caption = d.caption(sel);
        e.caption_of = e.selected;
    }
    ImGui::Text("Caption of stop %d", e.selected + 1);
    ImGui::SameLine();
    ImGui::TextDisabled("(several lines; **bold**; maths as plain text)");
    if (ImGui::InputTextMultiline("##caption", &e.caption,
                                  ImVec2(-1, ImGui::GetTextLineHeight() * 5))) {
        d.set_caption(sel, e.caption);
        e.dirty = true;
    }
    report_item("editor/caption");
    if (ImGui::Button("Up") && d.move(sel, true)) {
        --e.selected;
        e.caption_of = -1;
        changed(e);
    }
    ImGui::SameLine();
    if (ImGui::Button("Down") && d.move(sel, false)) {
        ++e.selected;
        e.caption_of = -1;
        changed(e);
    }
    ImGui::SameLine();
    ImGui::BeginDisabled(d.size() <= 1);
    if (ImGui::Button("Delete")) {
        d.remove(sel);
        e.caption_of = -1;
        changed(e);
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!e.problem.empty());
    const bool play = ImGui::Button("Play from here");
    report_item("editor/play");
    ImGui::EndDisabled();
    if (play) request_play_draft(ctx, sel); // unsaved changes are asked about first

    ImGui::Separator();
    ImGui::PushTextWrapPos(0);
    if (!e.problem.empty())
        ImGui::TextColored(error_text_color(), "Does not replay: %s", e.problem.c_str());
    if (!e.note.empty()) ImGui::TextDisabled("%s", e.note.c_str());
    ImGui::PopTextWrapPos();
    const bool save = ImGui::Button(e.path.empty() ? "Save..." : "Save as...");
    report_item("editor/save");
    if (save) request_save_lesson_dialog(ctx);
    ImGui::SameLine();
    if (ImGui::Button("Close")) open = false;
    ImGui::End();
    if (!open) e.open = false;
}

} // namespace isoparm::ui
