// Writing a lesson while recording: Add stop here (a caption of several lines, **bold**, maths
// as plain text) and Add expectation (facts of the document as it is now, ticked to keep);
// and the lesson editor and Exercise panels drawn in their turn.
#include <algorithm>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <string>
#include <vector>

#include "ui/course_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/ui_report.hpp"

namespace isoparm::ui {

namespace {

bool escape_pressed() {
    return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false);
}

void centre_next(float width) {
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + vp->Size.x * 0.5f, vp->Pos.y + vp->Size.y * 0.5f),
                            ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(width, vp->Size.x * 0.9f), 0));
}

void add_stop_dialog(AppContext& ctx) {
    CourseState& c = ctx.ui.course;
    if (c.add_stop_request) {
        ImGui::OpenPopup("Add stop here");
        c.add_stop_request = false;
    }
    centre_next(480 * ctx.ui.scale());
    if (!ImGui::BeginPopupModal("Add stop here", nullptr, 0)) return;
    ImGui::TextWrapped("The lesson will stop here, showing this caption over the scene as it "
                       "is now. Several lines are fine; **bold** stands out; write maths as "
                       "plain text (w22 = 0.3, S(u, v)).");
    if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
    ImGui::InputTextMultiline("##stop_caption", &c.stop_caption,
                              ImVec2(-1, ImGui::GetTextLineHeight() * 6));
    report_item("stop/caption");
    const bool add = ImGui::Button("Add stop");
    report_item("stop/add");
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape_pressed()) ImGui::CloseCurrentPopup();
    if (add) {
        add_stop_here(ctx, c.stop_caption);
        c.stop_caption.clear();
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

void add_expectation_dialog(AppContext& ctx) {
    CourseState& c = ctx.ui.course;
    if (c.add_expectation_request) {
        ImGui::OpenPopup("Add expectation");
        c.add_expectation_request = false;
    }
    centre_next(560 * ctx.ui.scale());
    if (!ImGui::BeginPopupModal("Add expectation", nullptr, 0)) return;
    ImGui::TextWrapped("What holds now, as the lesson will check it when played (a student's "
                       "change that breaks it is shown in the caption box). Tick what matters:");
    const float list_h = std::min(ImGui::GetTextLineHeightWithSpacing() * 12,
                                  ImGui::GetMainViewport()->Size.y * 0.5f);
    if (ImGui::BeginChild("##facts", ImVec2(0, list_h), true)) {
        for (std::size_t k = 0; k < c.facts.size(); ++k) {
            bool on = c.chosen[k] != 0;
            if (ImGui::Checkbox((c.facts[k].text + "##fact" + std::to_string(k)).c_str(), &on))
                c.chosen[k] = on ? 1 : 0;
            report_item("expect/fact" + std::to_string(k));
        }
    }
    ImGui::EndChild();
    const auto ticked = static_cast<std::size_t>(std::count(c.chosen.begin(), c.chosen.end(), 1));
    ImGui::BeginDisabled(ticked == 0);
    const bool add = ImGui::Button(ticked > 1 ? "Add expectations" : "Add expectation");
    report_item("expect/add");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || escape_pressed()) ImGui::CloseCurrentPopup();
    if (add) {
        std::vector<scene::Fact> kept;
        for (std::size_t k = 0; k < c.facts.size(); ++k)
            if (c.chosen[k]) kept.push_back(c.facts[k]);
        add_expectations(ctx, kept);
        ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
}

} // namespace

void draw_course_panels(AppContext& ctx) {
    ctx.ui.course.floating.clear(); // filled again by the two panels below
    draw_lesson_editor_panel(ctx);
    draw_exercise_panel(ctx);
    add_stop_dialog(ctx);
    add_expectation_dialog(ctx);
}

} // namespace isoparm::ui
