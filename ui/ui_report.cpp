// The GUI scenario tests' view of the window (see ui_report.hpp).
#include "ui/ui_report.hpp"

#include <cstdio>
#include <cstdlib>
#include <imgui.h>
#include <imgui_internal.h> // which window a menu title is in (the bar or a menu)
#include <map>
#include <nlohmann/json.hpp>

#include "core/scene/atomic_file.hpp"
#include "ui/app_context.hpp"

namespace isoparm::ui {

namespace {

struct Report {
    std::string path;
    std::map<std::string, std::array<float, 4>> rects;
    std::map<std::string, nlohmann::json> facts;
    std::string last_written;
};

Report& report() {
    static Report r = [] {
        Report x;
        if (const char* p = std::getenv("ISOPARM_UI_REPORT"); p && *p) x.path = p;
        return x;
    }();
    return r;
}

} // namespace

bool ui_report_enabled() {
    return !report().path.empty();
}

void report_rect(const std::string& name, float x, float y, float w, float h) {
    if (ui_report_enabled()) report().rects[name] = {x, y, w, h};
}

void report_point(const std::string& name, float x, float y) {
    report_rect(name, x, y, 0, 0);
}

void report_fact(const std::string& name, double value) {
    if (ui_report_enabled()) report().facts[name] = value;
}

void report_fact(const std::string& name, const std::vector<double>& values) {
    if (ui_report_enabled()) report().facts[name] = values;
}

void report_item(const std::string& name) {
    if (!ui_report_enabled()) return;
    const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
    report_rect(name, a.x, a.y, b.x - a.x, b.y - a.y);
}

void flush_ui_report(const AppContext& ctx) {
    Report& r = report();
    if (r.path.empty()) return;
    nlohmann::json j;
    for (const auto& [name, rect] : r.rects) j["rects"][name] = rect;
    j["facts"] = nlohmann::json::object();
    for (const auto& [name, value] : r.facts) j["facts"][name] = value;
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    j["window"] = {vp->Size.x, vp->Size.y};
    j["objects"] = ctx.doc.objects.size();
    j["density"] = ctx.doc.view.display.density; // the scene's display density
    const doc::Object* sel = ctx.doc.selected();
    j["selected"] = sel ? sel->name : "";
    j["point"] = {ctx.doc.view.selection.i, ctx.doc.view.selection.j};
    j["dirty"] = ctx.dirty();
    j["undo"] = ctx.history.can_undo() ? ctx.history.undo_label() : "";
    j["undo_steps"] = ctx.history.size();
    j["selection_size"] = ctx.ui.modeler.selection.points.size();
    j["presentation"] = ctx.ui.presentation;
    j["indicator"] = {ctx.doc.view.indicator.x, ctx.doc.view.indicator.y};
    j["typing"] = ImGui::GetIO().WantTextInput; // a text field has the keyboard
    // The selected object's (its own toggle, else the scene's default).
    j["control_points"] =
        doc::display_of(ctx.doc.view, ctx.doc.view.selection.object).control_points;
    j["font_pixels"] = ImGui::GetFontSize();
    // Which frame this is: a scenario waits for a layout that two frames agree on (a font or
    // a mode changes the layout over a frame or two) before it clicks on it.
    j["frame"] = ImGui::GetFrameCount();
    j["recording"] = ctx.recorder ? static_cast<long>(ctx.recorder->step_count()) : -1;
    if (ctx.ui.lesson)
        j["lesson"] = {{"next", ctx.ui.lesson->next},
                       {"caption", ctx.ui.lesson->caption},
                       {"stop", ctx.ui.lesson->stop},
                       {"stops", ctx.ui.lesson->stops()},
                       {"path", ctx.ui.lesson->path},
                       {"unmet", ctx.ui.lesson->unmet},
                       {"refused", ctx.ui.lesson->refused},
                       // The caption box was not placed again this frame: it is where it stays.
                       {"settled", ctx.ui.course.caption_box.settling == 0}};
    if (ctx.recorder) j["recording_stops"] = ctx.recorder->stop_count();
    if (const LessonEditorState& e = ctx.ui.course.editor; e.open && e.draft)
        j["editor"] = {{"path", e.path}, {"stops", e.draft->size()}, {"problem", e.problem}};
    if (const ExerciseState& x = ctx.ui.course.exercise;
        ctx.ui.course.exercise_open && x.exercise) {
        j["exercise"] = {{"path", x.path}, {"checked", x.grade.has_value()}};
        if (x.grade) {
            j["exercise"]["passed"] = x.grade->passed();
            j["exercise"]["passed_count"] = x.grade->passed_count();
            const scene::CheckResult* f = x.grade->first_failure();
            j["exercise"]["first_failure"] = f ? f->message : "";
        }
    }
    r.rects.clear(); // what the next frame draws, it reports again
    r.facts.clear();
    std::string text = j.dump(1);
    if (text == r.last_written) return;
    // Through the one atomic writer: a reader never sees half a report.
    if (scene::write_file_atomically(r.path, text).ok()) r.last_written = std::move(text);
}

} // namespace isoparm::ui

namespace isoparm::ui {

bool begin_menu(const char* label, bool enabled) {
    // ImGui 1.86 opens a menu bar's menu as soon as the pointer moves onto its title while
    // another is open, and the click a person then makes on that title closed it again: such a
    // click keeps it open (a click on a title opened by a click still closes it).
    static ImGuiID clicked_title = 0, reopen = 0; // the bar menu last opened by a click
    ImGuiWindow* window = ImGui::GetCurrentWindow();
    const bool bar = window->DC.LayoutType == ImGuiLayoutType_Horizontal;
    const ImGuiID id = window->GetID(label);
    // The frame after the click (a popup opened during the click's own frame is closed again
    // at its end, as a click outside the open menus).
    if (bar && reopen == id) {
        reopen = 0;
        ImGui::OpenPopup(label);
    }
    // The title's rectangle, as BeginMenu lays it out in a bar (the pointer's test).
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const ImVec2 size(ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetStyle().ItemSpacing.x,
                      ImGui::GetFrameHeight());
    const bool was_open = bar && ImGui::IsPopupOpen(id, ImGuiPopupFlags_None);
    const bool click = bar && ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
                       ImGui::IsMouseHoveringRect(at, ImVec2(at.x + size.x, at.y + size.y));
    const bool open = ImGui::BeginMenu(label, enabled);
    report_item(std::string("menu/") + label);
    if (click) {
        if (was_open && !open && clicked_title != id) {
            reopen = id; // opened by moving onto its title: the click keeps it open
            clicked_title = id;
        } else {
            clicked_title = was_open ? 0 : id; // a second click on a clicked menu closes it
        }
    }
    return open;
}

bool menu_item(const char* label, const char* shortcut, bool selected, bool enabled) {
    const bool picked = ImGui::MenuItem(label, shortcut, selected, enabled);
    report_item(std::string("menu/") + label);
    return picked;
}

bool menu_item(const char* label, const char* shortcut, bool* selected, bool enabled) {
    const bool picked = ImGui::MenuItem(label, shortcut, selected, enabled);
    report_item(std::string("menu/") + label);
    return picked;
}

} // namespace isoparm::ui
