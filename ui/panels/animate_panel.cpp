// The Animate panel (Display > Animate...): a weight, a knot, the (u, v) indicator along a line
// or a circle, de Boor's step or an implicit parameter on a slider that plays, pauses, loops and
// has a speed; Keep makes the value shown one undo step, Stop puts everything back. And the
// question asked before a constructed object's own points are edited.
#include <algorithm>
#include <cmath>
#include <imgui.h>
#include <string>

#include "core/doc/commands_construction.hpp"
#include "core/geom/knots.hpp"
#include "ui/animation_actions.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

// The target the form describes, from the document as it is (the selected point, the current
// surface or curve, the selected implicit).
doc::AnimationTarget target_of_form(const AppContext& ctx) {
    const AnimationState& a = ctx.ui.modeler.animation;
    doc::AnimationTarget t;
    t.kind = static_cast<doc::AnimatedKind>(a.form_kind);
    t.from = a.form_from;
    t.to = a.form_to;
    const doc::Object* sel = ctx.doc.selected();
    switch (t.kind) {
    case doc::AnimatedKind::weight:
        t = weight_target_of_selection(ctx.doc);
        t.from = a.form_from;
        t.to = a.form_to;
        break;
    case doc::AnimatedKind::knot: {
        const doc::Object* cur = sel;
        if (!cur || (!cur->surface() && !cur->curve())) current_surface(ctx.doc, &cur);
        t.object = cur ? cur->id : 0;
        t.dir = a.form_dir == 0 ? geom::Dir::u : geom::Dir::v;
        t.k = a.form_k;
        break;
    }
    case doc::AnimatedKind::indicator_line:
        t.uv_from = {0.05, ctx.doc.view.indicator.y};
        t.uv_to = {0.95, ctx.doc.view.indicator.y};
        break;
    case doc::AnimatedKind::indicator_circle:
        t.centre = {0.5, 0.5};
        t.radius = 0.35;
        break;
    case doc::AnimatedKind::deboor_step:
        break;
    case doc::AnimatedKind::implicit_parameter:
        if (sel && sel->implicit() && !sel->implicit()->parameter_names.empty()) {
            t.object = sel->id;
            t.parameter = sel->implicit()->parameter_names.front();
        }
        break;
    }
    return t;
}

// Sensible ranges when the kind changes: weights 0..5, a knot between its neighbours, de
// Boor's steps, a parameter around its value.
void default_range(AppContext& ctx) {
    AnimationState& a = ctx.ui.modeler.animation;
    switch (static_cast<doc::AnimatedKind>(a.form_kind)) {
    case doc::AnimatedKind::weight:
        a.form_from = 0;
        a.form_to = 5;
        break;
    case doc::AnimatedKind::knot: {
        const doc::Object* cur = ctx.doc.selected();
        if (!cur || (!cur->surface() && !cur->curve())) current_surface(ctx.doc, &cur);
        const geom::Knots* U = nullptr;
        int p = 1;
        if (cur && cur->surface()) {
            const geom::Dir d = a.form_dir == 0 ? geom::Dir::u : geom::Dir::v;
            U = &cur->surface()->knots(d);
            p = cur->surface()->degree(d);
        } else if (cur && cur->curve()) {
            U = &cur->curve()->knots;
            p = cur->curve()->degree;
        }
        if (U && static_cast<int>(U->size()) > 2 * p + 2) {
            a.form_k = p + 1; // the first interior knot
            const double lo = (*U)[static_cast<std::size_t>(p)];
            const double hi = (*U)[static_cast<std::size_t>(p + 2)];
            a.form_from = lo + 0.05 * (hi - lo);
            a.form_to = hi - 0.05 * (hi - lo);
        }
        break;
    }
    case doc::AnimatedKind::deboor_step:
        a.form_from = 0;
        a.form_to = 6;
        break;
    case doc::AnimatedKind::implicit_parameter: {
        const doc::Object* sel = ctx.doc.selected();
        if (sel && sel->implicit() && !sel->implicit()->parameter_values.empty()) {
            const double v = sel->implicit()->parameter_values.front();
            a.form_from = v * 0.5;
            a.form_to = v * 1.5 + (v == 0 ? 1 : 0);
        }
        break;
    }
    default:
        a.form_from = 0;
        a.form_to = 1;
        break;
    }
}

} // namespace

void draw_animate_panel(AppContext& ctx) {
    AnimationState& a = ctx.ui.modeler.animation;
    if (!a.open) return;
    const float k = ctx.ui.scale();
    const Rect& v = ctx.ui.view_rect;
    ImGui::SetNextWindowPos(ImVec2(v.x + v.w - 8 * k, v.y + v.h - 8 * k), ImGuiCond_Appearing,
                            ImVec2(1, 1));
    ImGui::SetNextWindowSize(ImVec2(360 * k, 0), ImGuiCond_Appearing);
    // A window made after the panels goes to the back in ImGui 1.86: bring it forward.
    if (a.focus) {
        ImGui::SetNextWindowFocus();
        a.focus = false;
    }
    bool open = true;
    if (!ImGui::Begin("Animate", &open,
                      ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return;
    }
    report_item("animate/window");
    const char* kinds[] = {"weight of the selected point", "knot",         "(u, v) along a line",
                           "(u, v) around a circle",       "de Boor step", "implicit parameter"};
    ImGui::SetNextItemWidth(230 * k);
    if (ImGui::Combo("what", &a.form_kind, kinds, IM_ARRAYSIZE(kinds))) default_range(ctx);
    report_item("animate/kind");
    const auto kind = static_cast<doc::AnimatedKind>(a.form_kind);
    if (kind == doc::AnimatedKind::knot) {
        ImGui::SetNextItemWidth(60 * k);
        const char* dirs[] = {"u", "v"};
        ImGui::Combo("direction", &a.form_dir, dirs, 2);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(90 * k);
        ImGui::InputInt("index", &a.form_k);
    }
    const bool path =
        kind == doc::AnimatedKind::indicator_line || kind == doc::AnimatedKind::indicator_circle;
    if (!path) {
        ImGui::SetNextItemWidth(100 * k);
        ImGui::InputDouble("from", &a.form_from, 0, 0, "%.4g");
        report_item("animate/from");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(100 * k);
        ImGui::InputDouble("to", &a.form_to, 0, 0, "%.4g");
        report_item("animate/to");
    }
    ImGui::SetNextItemWidth(100 * k);
    ImGui::InputDouble("seconds a pass", &a.form_seconds, 0, 0, "%.3g");
    a.form_seconds = std::clamp(a.form_seconds, 0.1, 3600.0);
    ImGui::SameLine();
    const char* repeats[] = {"once", "loop", "bounce"};
    ImGui::SetNextItemWidth(90 * k);
    ImGui::Combo("##repeat", &a.form_repeat, repeats, 3);
    if (ImGui::Button("Animate this")) {
        const doc::AnimationTarget t = target_of_form(ctx);
        start_animation(ctx, t, a.form_seconds, static_cast<doc::Repeat>(a.form_repeat), true);
    }
    report_item("animate/start");
    if (!a.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, error_text_color());
        ImGui::TextWrapped("%s", a.error.c_str());
        ImGui::PopStyleColor();
    }

    if (a.active) {
        ImGui::Separator();
        AnimationPlayer& p = a.player;
        const std::string what = doc::describe(p.target);
        ImGui::TextUnformatted(what.c_str());
        if (ImGui::Button(p.playing ? "Pause" : "Play", ImVec2(70 * k, 0))) p.toggle();
        report_item("animate/play");
        ImGui::SameLine();
        float phase = static_cast<float>(p.phase);
        ImGui::SetNextItemWidth(-1);
        const std::string shown =
            path ? "(" + geom::format_short(doc::indicator_at(p.target, p.phase).x) + ", " +
                       geom::format_short(doc::indicator_at(p.target, p.phase).y) + ")"
            : kind == doc::AnimatedKind::deboor_step
                ? "step " + std::to_string(doc::step_at(p.target, p.phase))
                : geom::format_short(doc::value_at(p.target, p.phase));
        if (ImGui::SliderFloat("##phase", &phase, 0, 1, shown.c_str())) {
            p.seek(phase);
            p.pause();
        }
        report_item("animate/phase");
        float speed = static_cast<float>(p.speed);
        ImGui::SetNextItemWidth(150 * k);
        if (ImGui::SliderFloat("speed", &speed, 0.25f, 4.f, "%.2fx", ImGuiSliderFlags_Logarithmic))
            p.speed = speed;
        int rep = static_cast<int>(p.repeat);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(90 * k);
        if (ImGui::Combo("##playrepeat", &rep, repeats, 3))
            p.repeat = static_cast<doc::Repeat>(rep);
        const bool keepable = !path && kind != doc::AnimatedKind::deboor_step;
        if (ImGui::Button(keepable ? "Keep this value" : "Keep this position"))
            keep_animation_value(ctx);
        report_item("animate/keep");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Make the value shown an edit: one undo step (the animation is never "
                              "one by itself)");
        ImGui::SameLine();
        if (ImGui::Button("Stop")) stop_animation(ctx);
        report_item("animate/stop");
        report_fact("animate/phase", p.phase);
        report_fact("animate/playing", p.playing ? 1 : 0);
        if (keepable) report_fact("animate/value", doc::value_at(p.target, p.phase));
    }
    ImGui::End();
    if (!open) {
        stop_animation(ctx);
        a.open = false;
    }
}

void draw_detach_question(AppContext& ctx) {
    DetachQuestion& q = ctx.ui.modeler.detach;
    if (!begin_centered_modal("Detach?##question", q.open, 460 * ctx.ui.scale())) return;
    ImGui::TextWrapped("%s", q.text.c_str());
    ImGui::Spacing();
    if (ImGui::Button("Detach")) {
        ImGui::CloseCurrentPopup();
        answer_detach(ctx);
    }
    report_item("detach/yes");
    ImGui::SameLine();
    if (ImGui::Button("Keep it linked") ||
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape), false)) {
        q.then.reset();
        ImGui::CloseCurrentPopup();
    }
    report_item("detach/no");
    ImGui::EndPopup();
}

} // namespace isoparm::ui
