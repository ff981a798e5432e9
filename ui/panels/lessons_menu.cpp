// The Lessons menu: the shipped lessons by title with a one-line summary each, the user's own
// (My lessons, from $XDG_DATA_HOME/isoparm/lessons), and writing a lesson: recording with
// stops and expectations, saving it as a lesson, the lesson editor. The Exercises menu: the
// shipped exercises, opening one, checking it.
#include <algorithm>
#include <imgui.h>
#include <string>
#include <vector>

#include "ui/actions.hpp"
#include "ui/course_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/course_files.hpp"

namespace isoparm::ui {

namespace {

// The folders are read when the menu opens, not every frame: a lesson saved a moment ago is
// listed the next time the menu opens.
struct Listing {
    std::vector<CourseEntry> shipped, mine, exercises;
};

Listing& listing() {
    static Listing l;
    return l;
}

void refresh_listing() {
    Listing& l = listing();
    l.shipped = list_lessons(shipped_lessons_dir());
    l.mine = list_lessons(user_lessons_dir());
    l.exercises = list_exercises(shipped_exercises_dir());
}

// Title on the left, the summary greyed on the right (ImGui's shortcut column); the summary
// in full in the tooltip.
std::string pick_from(const std::vector<CourseEntry>& entries, const char* report_prefix) {
    std::string chosen;
    for (const CourseEntry& e : entries) {
        if (ImGui::MenuItem(e.title.c_str(), e.summary.empty() ? nullptr : e.summary.c_str()))
            chosen = e.path;
        report_item("menu/" + std::string(report_prefix) + e.title);
        if (ImGui::IsItemHovered() && !e.summary.empty()) ImGui::SetTooltip("%s", e.path.c_str());
    }
    return chosen;
}

} // namespace

void draw_lessons_menu(AppContext& ctx) {
    if (!begin_menu("Lessons")) return;
    if (ImGui::IsWindowAppearing()) refresh_listing();
    const Listing& l = listing();
    if (menu_item("Open lesson...")) request_open_lesson_dialog(ctx);
    ImGui::Separator();
    std::string lesson = pick_from(l.shipped, "lessons/");
    if (l.shipped.empty()) ImGui::TextDisabled("No shipped lessons found");
    ImGui::Separator();
    // The user's own, inline (a submenu beside this wide menu would open under the pointer):
    // the first few here, the rest one level down.
    ImGui::TextDisabled("My lessons (%s)", user_lessons_dir().c_str());
    constexpr std::size_t inline_mine = 6;
    const std::vector<CourseEntry> first(
        l.mine.begin(), l.mine.begin() + static_cast<long>(std::min(l.mine.size(), inline_mine)));
    if (std::string mine = pick_from(first, "my-lessons/"); !mine.empty()) lesson = mine;
    if (l.mine.size() > inline_mine && begin_menu("More of my lessons")) {
        const std::vector<CourseEntry> rest(l.mine.begin() + static_cast<long>(inline_mine),
                                            l.mine.end());
        if (std::string mine = pick_from(rest, "my-lessons/"); !mine.empty()) lesson = mine;
        ImGui::EndMenu();
    }
    if (l.mine.empty())
        ImGui::TextDisabled(
            "  none yet: Start recording a lesson, Add stop here, Save recording as lesson");
    ImGui::Separator();
    // Writing a lesson: record a session, mark its stops and what must hold there.
    if (!ctx.recorder) {
        if (menu_item("Start recording a lesson")) start_recording(ctx);
    } else {
        const std::string stops = std::to_string(ctx.recorder->stop_count());
        if (menu_item("Add stop here...")) request_add_stop(ctx);
        if (menu_item("Add expectation...")) request_add_expectation(ctx);
        if (menu_item(("Save recording as lesson... (" + stops + " stops)").c_str()))
            save_recording_as_lesson(ctx);
        report_item("menu/Save recording as lesson...");
    }
    if (menu_item("Lesson editor")) open_lesson_editor(ctx);
    ImGui::EndMenu();
    if (!lesson.empty()) request_open_lesson(ctx, lesson);
}

void draw_exercises_menu(AppContext& ctx) {
    if (!begin_menu("Exercises")) return;
    if (ImGui::IsWindowAppearing()) listing().exercises = list_exercises(shipped_exercises_dir());
    const std::string ex = pick_from(listing().exercises, "exercises/");
    if (listing().exercises.empty()) ImGui::TextDisabled("No exercises found");
    ImGui::Separator();
    if (menu_item("Open exercise...")) request_open_exercise_dialog(ctx);
    const bool open = ctx.ui.course.exercise_open && ctx.ui.course.exercise.exercise;
    if (menu_item("Check the exercise", nullptr, false, open)) check_exercise(ctx);
    ImGui::EndMenu();
    if (!ex.empty()) request_open_exercise(ctx, ex);
}

} // namespace isoparm::ui
