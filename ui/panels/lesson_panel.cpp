// The lesson's caption box over the 3D view: the caption, where the lesson stands, and Next
// (Right arrow or Page Down), Back, Restart and Close. It is placed off the point and the
// object the stop is about (ui/view/caption_place.hpp), moves again when they come under it,
// and stays where the user drags it until the next stop.
#include <algorithm>
#include <filesystem>
#include <imgui.h>
#include <string>

#include "ui/actions.hpp"
#include "ui/course_actions.hpp"
#include "ui/lesson.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/rich_text.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/caption_place.hpp"

namespace isoparm::ui {

namespace {

// Where the box goes this frame, or nothing (it stays where it is: placed, or dragged). At a
// new stop it is placed off the stop's point and object; where the view has no room beside
// the object, the camera frames the object in the part of the view the box leaves free.
std::optional<Rect> box_position(AppContext& ctx, const Lesson& lesson, float width,
                                 const CaptionFocus& focus) {
    CaptionBoxState& box = ctx.ui.course.caption_box;
    const float k = ctx.ui.scale();
    const Rect& view = ctx.ui.view_rect.w > 0 ? ctx.ui.view_rect : ctx.ui.drawing_rect;
    const float height = box.last_height > 0 ? box.last_height : 160 * k;
    const bool new_stop = box.placed_for != lesson.stop;
    // Placed with an estimate of its height (the last caption's): once this caption's own
    // is known (an auto-sized window takes a frame or two), placed again.
    const bool resized = !new_stop && !box.user_moved && std::abs(height - box.placed.h) > 2;
    bool covers = false;
    const Rect now{box.placed.x, box.placed.y, width, height};
    for (const Rect& p : focus.points) covers = covers || overlaps(now, p);
    if (!new_stop && !resized && (box.user_moved || !covers)) return std::nullopt;
    // A new stop, its real height, or the point came under the box (the camera turned).
    const Rect r = place_caption(view, width, height, focus, 8 * k, new_stop ? nullptr : &now);
    {
        // Wherever it goes (a new stop, its real height, a point that came under it), the
        // object it lands on is framed again beside it.
        float covered = 0;
        for (const Rect& o : focus.objects) covered += overlap_area(r, o);
        if (covered > 0) {
            // The points' disks (focus.points, 14 k around each point) stay clear of the box
            // too, not only their centres: otherwise a point at the free part's edge comes
            // under the box by a pixel and the box is placed again on every frame.
            const Rect free = free_beside(view, r);
            const float m = 14 * k;
            const Rect inside{free.x + m, free.y + m, std::max(0.f, free.w - 2 * m),
                              std::max(0.f, free.h - 2 * m)};
            fit_camera_into(ctx.ui.camera, focus_points(ctx.doc), view, inside);
            ctx.ui.camera_needs_fit = false;
        }
    }
    box.placed_for = lesson.stop;
    box.placed = r;
    box.user_moved = false;
    return r;
}

} // namespace

void draw_lesson_panel(AppContext& ctx) {
    if (!ctx.ui.lesson) return;
    Lesson& lesson = *ctx.ui.lesson;
    const float k = ctx.ui.scale();
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const Rect& view = ctx.ui.drawing_rect;
    const float width = std::max(std::min(520 * k, view.w - 16 * k), 240 * k);
    // The stop's subject on screen: the box keeps off it.
    CaptionFocus focus = caption_focus(ctx.doc, ctx.ui.camera, ctx.ui.view_rect, 14 * k);
    // The lesson editor and the Exercise panel float over the view too: the box keeps clear.
    for (const Rect& w : ctx.ui.course.floating) focus.windows.push_back(w);
    CaptionBoxState& placing = ctx.ui.course.caption_box;
    if (const std::optional<Rect> at = box_position(ctx, lesson, width, focus)) {
        ImGui::SetNextWindowPos(ImVec2(vp->Pos.x + at->x, vp->Pos.y + at->y), ImGuiCond_Always);
        ++placing.settling;
    } else {
        placing.settling = 0;
    }
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0), ImVec2(width, vp->Size.y * 0.5f));
    const ImGuiWindowFlags flags = ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                                   ImGuiWindowFlags_NoSavedSettings |
                                   ImGuiWindowFlags_NoFocusOnAppearing;
    bool open = true;
    const std::string title =
        "Lesson: " +
        (lesson.script.title.empty() ? std::filesystem::path(lesson.path).filename().string()
                                     : lesson.script.title) +
        "###lesson";
    if (ImGui::Begin(title.c_str(), &open, flags)) {
        CaptionBoxState& box = ctx.ui.course.caption_box;
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        box.last_height = size.y;
        // Dragged by its title bar: the user's place holds until the next stop.
        if (std::abs(pos.x - vp->Pos.x - box.placed.x) > 0.5f ||
            std::abs(pos.y - vp->Pos.y - box.placed.y) > 0.5f)
            box.user_moved = true;
        report_rect("lesson/box", pos.x, pos.y, size.x, size.y);
        for (std::size_t p = 0; p < focus.points.size(); ++p)
            report_rect("lesson/focus/point" + std::to_string(p), focus.points[p].x,
                        focus.points[p].y, focus.points[p].w, focus.points[p].h);
        for (std::size_t o = 0; o < focus.objects.size(); ++o)
            report_rect("lesson/focus/object" + std::to_string(o), focus.objects[o].x,
                        focus.objects[o].y, focus.objects[o].w, focus.objects[o].h);
        draw_rich_text(lesson.caption.empty() ? "(no caption yet)" : lesson.caption);
        for (const std::string& u : lesson.unmet)
            ImGui::TextColored(ImVec4(1, 0.72f, 0.3f, 1), "Not as the lesson expected: %s",
                               u.c_str());
        if (!lesson.refused.empty())
            ImGui::TextColored(ImVec4(1, 0.45f, 0.4f, 1), "This step could not be done: %s",
                               lesson.refused.c_str());
        ImGui::TextDisabled("Stop %zu of %zu", lesson.stop, lesson.stops());
        const bool can_go_on = !lesson.finished() && lesson.refused.empty();
        ImGui::BeginDisabled(!can_go_on);
        bool next = ImGui::Button(lesson.finished() ? "The end" : "Next  >");
        report_item("lesson/next");
        ImGui::EndDisabled();
        ImGui::SameLine();
        // Back: the lesson replayed from its start to the stop before this one.
        ImGui::BeginDisabled(lesson.stop <= 1);
        const bool back = ImGui::Button("<  Back");
        report_item("lesson/back");
        ImGui::EndDisabled();
        ImGui::SameLine();
        const bool restart = ImGui::Button("Restart");
        ImGui::SameLine();
        const bool edit = ImGui::Button("Edit...");
        report_item("lesson/edit");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The lesson editor: stops, captions, order; play from any stop");
        ImGui::SameLine();
        if (ImGui::Button("Close")) open = false;
        report_item("lesson/close");
        // Right arrow or Page Down: the next stop, as a presenter's clicker sends.
        if (can_go_on && !ImGui::GetIO().WantTextInput &&
            (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow), false) ||
             ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_PageDown), false)))
            next = true;
        if (next && can_go_on) lesson_next(ctx);
        if (restart) restart_lesson(ctx);
        if (back) lesson_goto(ctx, lesson.stop - 2);
        if (edit) open_lesson_editor(ctx);
    }
    ImGui::End();
    if (!open) ctx.ui.lesson.reset();
}

} // namespace isoparm::ui
