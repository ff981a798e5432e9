// The curve designer panel: the selected curve on its plane canvas, its points, weights,
// degree, knot mode, knots, knot insertion and elevation, de Boor's trace, basis functions
// and the exact primitives. Every edit is a command (core/doc/commands_curve.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <string>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/geom/basis.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/enum_combo.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/toolbox_actions.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/text_wrap.hpp"

namespace isoparm::ui {

namespace {

using namespace curve_designer;

const doc::CurveObject* selected_curve(const AppContext& ctx, const doc::Object** obj) {
    *obj = ctx.doc.selected();
    return *obj ? (*obj)->curve_object() : nullptr;
}

void warn_text(const AppContext& ctx, const std::string& text) {
    const ImVec4 warn = ctx.ui.presentation ? ImVec4(0.7f, 0.25f, 0, 1) : ImVec4(1, 0.72f, 0.3f, 1);
    ImGui::PushStyleColor(ImGuiCol_Text, warn);
    text_wrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

void hint_text(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    text_wrapped("%s", text);
    ImGui::PopStyleColor();
}

// A button for one command: greyed, with the command's own refusal as its tooltip, when the
// command would not apply (the panel does not repeat the command's rules).
bool command_button(const AppContext& ctx, const char* label, const doc::Command& cmd,
                    const char* tip) {
    const geom::Status st = cmd.check(ctx.doc);
    ImGui::BeginDisabled(!st.ok());
    const bool pressed = ImGui::Button(label);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        wrapped_tooltip(st.ok() ? std::string(tip) : st.error().message);
    return pressed;
}

// Runs a command; a refusal is kept for the panel to show (and the status bar shows it too).
bool run(AppContext& ctx, std::unique_ptr<doc::Command> cmd) {
    ctx.seal();
    const bool ok = ctx.execute(std::move(cmd));
    ctx.seal();
    ctx.ui.curve.message = ok ? std::string() : ctx.ui.status;
    return ok;
}

void plane_row(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c) {
    CurveDesignerState& cd = ctx.ui.curve;
    doc::CurvePlane plane = c.plane;
    ImGui::SetNextItemWidth(70 * ctx.ui.scale());
    if (enum_combo("Plane", plane)) run(ctx, doc::set_curve_plane(obj.id, plane, cd.carry_points));
    same_line_if_fits(toggle_width("move points with it"));
    ImGui::Checkbox("move points with it", &cd.carry_points);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("On: the drawing moves into the new plane (its two coordinates are\n"
                          "carried over). Off: only the canvas changes; the points stay.");
    if (c.plane == doc::CurvePlane::free3d) {
        ImGui::TextUnformatted("View");
        for (int v = 0; v < 3; ++v) {
            ImGui::SameLine();
            ImGui::RadioButton(plane_axes[v].name, &cd.view_plane, v);
        }
    }
}

void point_controls(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c) {
    const int i = ctx.doc.view.selection.object == obj.id ? ctx.doc.view.selection.i : -1;
    const geom::Curve& g = c.curve;
    if (i < 0 || i >= g.count()) {
        hint_text("Click a point on the canvas to select it.");
        return;
    }
    ImGui::AlignTextToFramePadding();
    ImGui::Text("P%d", i);
    glm::dvec3 p = g.points[static_cast<std::size_t>(i)];
    const char* labels[3] = {"x", "y", "z"};
    const float del_w = ImGui::CalcTextSize("Delete").x + ImGui::GetStyle().FramePadding.x * 2;
    const float field_w = (ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("P00").x - del_w -
                           ImGui::GetStyle().ItemSpacing.x * 4) /
                              3 -
                          ImGui::CalcTextSize("x").x - ImGui::GetStyle().ItemInnerSpacing.x;
    // In a row while each field shows a whole value, else one under the other.
    const float whole = ImGui::CalcTextSize("-00.000").x + ImGui::GetStyle().FramePadding.x * 2;
    const bool row = field_w >= whole;
    const float label_w = ImGui::CalcTextSize("x").x + ImGui::GetStyle().ItemInnerSpacing.x;
    for (int a = 0; a < 3; ++a) {
        if (row || a == 0) ImGui::SameLine();
        ImGui::SetNextItemWidth(row ? field_w
                                    : std::max(ImGui::GetContentRegionAvail().x - label_w, whole));
        double value = p[a];
        if (ImGui::InputDouble(labels[a], &value, 0, 0, "%.3f") && std::isfinite(value) &&
            value != p[a] && may_edit_points(ctx, obj.id)) {
            p[a] = value;
            if (!ctx.execute(point_move_command(ctx, obj.id, i, -1, p)))
                ctx.ui.curve.message = ctx.ui.status;
        }
        if (ImGui::IsItemDeactivatedAfterEdit()) ctx.seal();
    }
    same_line_if_fits(button_width("Delete"));
    // The curve `g` refers to is replaced by a deletion: nothing below may read it this frame.
    if (command_button(ctx, "Delete", *doc::delete_curve_point(obj.id, i),
                       "Deletes this control point; the knots follow the knot mode.") &&
        run(ctx, doc::delete_curve_point(obj.id, i)))
        return;

    // The weight of a rational curve; a non-rational one can be made rational.
    if (!geom::is_rational(g.type)) {
        ImGui::AlignTextToFramePadding();
        ImGui::TextDisabled("w%d = 1 (%s)", i, geom::name_of(g.type));
        same_line_if_fits(button_width("Make rational"));
        if (ImGui::SmallButton("Make rational")) {
            doc::CurveObject r = c;
            r.curve.type = geom::is_bezier(g.type) ? geom::SplineType::rational_bezier
                                                   : geom::SplineType::nurbs;
            run(ctx, doc::edit_shape(obj.id, r, "Make " + obj.name + " rational"));
        }
        return;
    }
    const double w = g.weights[static_cast<std::size_t>(i)];
    ImGui::AlignTextToFramePadding();
    ImGui::Text("w%d", i);
    ImGui::SameLine();
    const float field = 80 * ctx.ui.scale();
    ImGui::SetNextItemWidth(
        std::max(ImGui::GetContentRegionAvail().x - field - ImGui::GetStyle().ItemSpacing.x, 40.f));
    const double lo = -2.0, hi = 6.0;
    double slider = w;
    if (ImGui::SliderScalar("##cweight", ImGuiDataType_Double, &slider, &lo, &hi, "%.3f") &&
        slider != w)
        ctx.execute(doc::set_weight(obj.id, i, -1, slider));
    if (ImGui::IsItemDeactivated()) ctx.seal();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(field);
    double typed = w;
    if (ImGui::InputDouble("##cweight_typed", &typed, 0, 0, "%.4g") && std::isfinite(typed) &&
        typed != w)
        ctx.execute(doc::set_weight(obj.id, i, -1, typed));
    if (ImGui::IsItemDeactivatedAfterEdit()) ctx.seal();
}

void degree_and_knots(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c) {
    CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    const geom::Curve& g = c.curve;
    int degree = g.degree;
    ImGui::SetNextItemWidth(90 * k);
    if (ImGui::InputInt("Degree", &degree, 1, 1, ImGuiInputTextFlags_EnterReturnsTrue) &&
        degree != g.degree)
        run(ctx, doc::set_curve_degree(obj.id, degree));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Sets the degree p (1..%d for %d points): the knots are recomputed and "
                          "the shape changes.",
                          g.count() - 1, g.count());
    same_line_if_fits(button_width("Elevate"));
    if (command_button(ctx, "Elevate", *doc::elevate_degree(obj.id, geom::Dir::u),
                       "Degree elevation (Piegl & Tiller A5.9): p + 1, more points, same shape."))
        run(ctx, doc::elevate_degree(obj.id, geom::Dir::u));

    doc::CurveKnotMode mode = c.knot_mode;
    ImGui::SetNextItemWidth(150 * k);
    if (enum_combo("Knots", mode)) run(ctx, doc::set_curve_knot_mode(obj.id, mode));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("How knots are chosen when points are added or deleted or the degree\n"
                          "changes: clamped uniform; averaged (P&T eq. 9.8) from the chord\n"
                          "lengths of the control polygon or their square roots (centripetal);\n"
                          "or custom: your knots, dragged on the strip below.");

    // The knot vector in full, as the textbooks write it.
    std::string knots = "U = [";
    for (std::size_t q = 0; q < g.knots.size(); ++q) {
        knots += (q ? ", " : "") + geom::format_short(g.knots[q]);
    }
    knots += "]";
    hint_text(knots.c_str());
    (void)cd;
}

void refine_controls(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c) {
    CurveDesignerState& cd = ctx.ui.curve;
    const geom::Curve& g = c.curve;
    const double t = ctx.ui.curve.trace_param(g);
    const std::string label = "t = " + geom::format_short(t);
    // The slider no narrower than its value; the check box and the button wrap onto the next
    // line where the column is narrow ("Insert knot" was cut on a projector).
    ImGui::SetNextItemWidth(
        std::max(ImGui::GetContentRegionAvail().x * 0.5f,
                 ImGui::CalcTextSize(label.c_str()).x + ImGui::GetStyle().FramePadding.x * 4));
    const double zero = 0, one = 1;
    ImGui::SliderScalar("##trace_t", ImGuiDataType_Double, &cd.trace_t, &zero, &one, label.c_str());
    same_line_if_fits(toggle_width("de Boor"));
    ImGui::Checkbox("de Boor", &cd.trace);
    same_line_if_fits(button_width("Insert knot"));
    if (command_button(ctx, "Insert knot", *doc::insert_knot(obj.id, geom::Dir::u, t),
                       "Knot insertion at t (Boehm, P&T A5.1): one more point, same shape."))
        run(ctx, doc::insert_knot(obj.id, geom::Dir::u, t));
    if (cd.trace) {
        const geom::DeBoorTriangle tri = geom::deboor_curve(g, t);
        const auto p = geom::DeBoorTriangle::cartesian(tri.levels.back().front());
        char text[160];
        if (p)
            std::snprintf(text, sizeof text,
                          "t in [u%d, u%d): de Boor blends P%d..P%d in %d levels; C(t) = (%s, "
                          "%s, %s)",
                          tri.span, tri.span + 1, tri.first_index, tri.first_index + g.degree,
                          g.degree, geom::format_short(p->x).c_str(),
                          geom::format_short(p->y).c_str(), geom::format_short(p->z).c_str());
        else
            std::snprintf(text, sizeof text, "C(t) does not exist at t (zero weight sum)");
        hint_text(text);
        // The colour key of the canvas: one colour per level, the curve point red.
        for (int lv = 1; lv <= g.degree; ++lv) {
            if (lv > 1) ImGui::SameLine();
            const ImU32 col = level_color(lv, g.degree);
            ImGui::TextColored(ImGui::ColorConvertU32ToFloat4(col),
                               lv == g.degree ? "C(t)" : "level %d", lv);
        }
    }
}

// The toolbox at the knot nearest t (Curve menu too): the shape may change, within the
// tolerance, and the button's tooltip says why not when it cannot.
void toolbox_row(AppContext& ctx) {
    struct Entry {
        Tool tool;
        const char* label;
        const char* tip;
    };
    const Entry entries[] = {
        {Tool::remove_knot, "Remove knot",
         "Knot removal (P&T A5.8) of the knot nearest t, "
         "within the tolerance (Curve menu)."},
        {Tool::reduce_degree, "Reduce",
         "Degree reduction by one (P&T A5.11) within the tolerance."},
        {Tool::split_knot, "Split knot",
         "DesignMentor's knot splitting: a multiple knot becomes "
         "a simple knot just before it plus one copy fewer."},
        {Tool::close, "Close", "The closed (periodic) curve of this polygon: C(p-1) at the seam."},
    };
    bool first = true;
    for (const Entry& e : entries) {
        const ActionState a = tool_state(ctx, e.tool, geom::Dir::u, true);
        if (!first) same_line_if_fits(button_width(e.label));
        first = false;
        ImGui::BeginDisabled(!a.enabled);
        const bool pressed = ImGui::Button(e.label);
        ImGui::EndDisabled();
        report_item(std::string("curve/") + e.label);
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            wrapped_tooltip(a.enabled ? a.label + ": " + e.tip : a.why);
        if (pressed) run_tool(ctx, e.tool, geom::Dir::u, true);
    }
}

void primitives(AppContext& ctx, const doc::CurveObject* c) {
    CurveDesignerState& cd = ctx.ui.curve;
    const doc::CurvePlane plane =
        c && c->plane != doc::CurvePlane::free3d ? c->plane : doc::CurvePlane::xy;
    const PlaneAxes ax = plane_axes[static_cast<int>(plane)];
    auto in_plane = [&](float a, float b) {
        glm::dvec3 p(0);
        p[ax.a] = a;
        p[ax.b] = b;
        return p;
    };
    ImGui::Text("In the %s plane (first axis %c, second %c):", ax.name, "xyz"[ax.a], "xyz"[ax.b]);
    auto add = [&](geom::Expected<doc::Object> o) {
        if (!o) {
            ctx.ui.curve.message = o.error().message;
            return;
        }
        ctx.seal();
        if (ctx.execute(doc::add_object(std::move(o).value())))
            ctx.doc.view.selection = {ctx.doc.objects.back().id, -1, -1};
        ctx.seal();
    };
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    ImGui::InputFloat4("from, to##line", cd.line_end, "%.2f");
    ImGui::SameLine();
    if (ImGui::Button("Line"))
        add(doc::line_object("line", plane, in_plane(cd.line_end[0], cd.line_end[1]),
                             in_plane(cd.line_end[2], cd.line_end[3])));
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    ImGui::InputFloat3("centre, r", cd.primitive, "%.2f");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    ImGui::InputFloat2("start, end (deg)", cd.primitive + 3, "%.1f");
    const glm::dvec3 centre = in_plane(cd.primitive[0], cd.primitive[1]);
    if (ImGui::Button("Arc"))
        add(doc::arc_object("arc", plane, centre, cd.primitive[2], cd.primitive[3],
                            cd.primitive[4]));
    ImGui::SameLine();
    if (ImGui::Button("Circle")) add(doc::circle_object("circle", plane, centre, cd.primitive[2]));
    ImGui::SameLine();
    hint_text("exact rational quadratics (P&T A7.1)");
}

// Everything under the canvas (beside it on the stage): hints, the selected point, degree and
// knots, the knot strip, refinement, analysis, the toolbox, curvature and basis plots.
void curve_controls(AppContext& ctx, std::uint64_t id) {
    CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    const doc::Object* obj = nullptr;
    const doc::CurveObject* c = selected_curve(ctx, &obj);
    if (!c) return;
    hint_text("Click: add a point   Ctrl+click a leg: insert   drag: move (Alt: no snap)   Del: "
              "delete   wheel: zoom   right-drag: pan");
    // Points before the first and after the last (a leg's insertion cannot reach the ends), and
    // the canvas framed again.
    {
        const geom::Curve& g = c->curve;
        const int n = g.count();
        const glm::dvec3 first = g.points.front(), last = g.points.back();
        const glm::dvec3 before =
            n > 1 ? first + (first - g.points[1]) : first - glm::dvec3(0.5, 0, 0);
        const glm::dvec3 after = n > 1 ? last + (last - g.points[static_cast<std::size_t>(n - 2)])
                                       : last + glm::dvec3(0.5, 0, 0);
        if (command_button(ctx, "Add before P0", *doc::insert_curve_point(id, 0, before),
                           "A new first point, continuing the polygon's first leg backwards") &&
            may_edit_points(ctx, id) && run(ctx, doc::insert_curve_point(id, 0, before)))
            ctx.doc.view.selection = {id, 0, -1};
        report_item("curve/add_first");
        ImGui::SameLine();
        const std::string last_label = "Add after P" + std::to_string(n - 1);
        if (command_button(ctx, last_label.c_str(), *doc::insert_curve_point(id, n, after),
                           "A new last point, continuing the polygon's last leg") &&
            may_edit_points(ctx, id) && run(ctx, doc::insert_curve_point(id, n, after)))
            ctx.doc.view.selection = {id, n, -1};
        report_item("curve/add_last");
        ImGui::SameLine();
        if (ImGui::Button("Fit")) fit_curve_canvas(cd);
        report_item("curve/fit");
    }
    if (!(c = selected_curve(ctx, &obj))) return;
    if (!cd.message.empty()) warn_text(ctx, cd.message);

    // Delete key: the selected point of this curve, unless a field has the keyboard.
    if (!ImGui::GetIO().WantTextInput &&
        ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) &&
        ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Delete), false) &&
        ctx.doc.view.selection.object == id && ctx.doc.view.selection.has_point())
        run(ctx, doc::delete_curve_point(id, ctx.doc.view.selection.i));

    if (!(c = selected_curve(ctx, &obj))) return;
    point_controls(ctx, *obj, *c);
    if (!(c = selected_curve(ctx, &obj))) return;
    degree_and_knots(ctx, *obj, *c);
    if (!(c = selected_curve(ctx, &obj))) return;
    {
        const ImVec2 p = ImGui::GetCursorScreenPos();
        const float h = ImGui::GetTextLineHeight() * 2 + 20 * k;
        knot_strip(ctx, *obj, *c, {p.x, p.y, ImGui::GetContentRegionAvail().x, h});
        ImGui::SetCursorScreenPos(ImVec2(p.x, p.y + h + ImGui::GetStyle().ItemSpacing.y));
    }
    if (!(c = selected_curve(ctx, &obj))) return;
    refine_controls(ctx, *obj, *c);
    analysis_toggles(ctx);
    if (!(c = selected_curve(ctx, &obj))) return;
    toolbox_row(ctx);
    if (!(c = selected_curve(ctx, &obj))) return;
    if (ImGui::CollapsingHeader("Curvature")) {
        const ImVec2 p = ImGui::GetCursorScreenPos();
        curvature_plot(ctx, c->curve, {p.x, p.y, ImGui::GetContentRegionAvail().x, 80 * k});
    }
    if (ImGui::CollapsingHeader("Basis functions", ImGuiTreeNodeFlags_DefaultOpen)) {
        const int sel = ctx.doc.view.selection.object == id ? ctx.doc.view.selection.i : -1;
        const ImVec2 p = ImGui::GetCursorScreenPos();
        basis_plot(ctx, *c, sel, {p.x, p.y, ImGui::GetContentRegionAvail().x, 90 * k});
        // Partition of unity at t: the functions sum to 1 wherever the curve exists.
        const auto& g = c->curve;
        const double t = ctx.ui.curve.trace_param(g);
        if (const auto r = geom::rational_basis(g.knots, g.degree, g.weights, t)) {
            double sum = 0;
            for (double v : (*r)[0]) sum += v;
            const std::string text =
                std::string("Sum of all ") + (geom::is_rational(g.type) ? "R_i" : "N_i") +
                " at t = " + geom::format_short(t) + ": " + geom::format_short(sum, 7);
            hint_text(text.c_str());
        }
        if (sel >= 0) {
            hint_text(("The selected point's function is non-zero on [u" + std::to_string(sel) +
                       ", u" + std::to_string(sel + g.degree + 1) +
                       "): moving the point changes only that part of the curve.")
                          .c_str());
        }
    }
    if (ImGui::CollapsingHeader("Primitives")) primitives(ctx, c);
}

} // namespace

void draw_curve_designer_panel(AppContext& ctx) {
    note_hovered_view(ctx, StageView::curve);
    CurveDesignerState& cd = ctx.ui.curve;
    const doc::Object* obj = nullptr;
    const doc::CurveObject* c = selected_curve(ctx, &obj);
    if (!c) {
        text_wrapped("Select a curve (Surface > Select) or make one (Curve > New curve).");
        return;
    }
    const std::uint64_t id = obj->id;
    const float k = ctx.ui.scale();
    const bool staged = on_stage(ctx, StageView::curve);
    {
        const geom::Curve& g = c->curve;
        const std::string title = obj->name + ": " + geom::name_of(g.type) + ", degree " +
                                  std::to_string(g.degree) + ", " + std::to_string(g.count()) +
                                  " points";
        const float room =
            ImGui::GetContentRegionAvail().x -
            (staged ? 0.f : ImGui::GetFrameHeight() + ImGui::GetStyle().ItemSpacing.x);
        const std::string shown = shortened(title, room, imgui_measure());
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(shown.c_str());
        if (shown != title && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", title.c_str());
        if (!staged) stage_button(ctx, StageView::curve);
    }
    plane_row(ctx, *obj, *c);
    if (!(c = selected_curve(ctx, &obj))) return;

    // The canvas: square while the panel allows, leaving room for the controls below; on the
    // stage it takes the height, the controls beside it.
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    if (staged) {
        const float w = std::max(std::min(avail.x * 0.64f, avail.x - 260 * k), avail.x * 0.5f);
        plane_canvas(ctx, *obj, *c, {origin.x, origin.y, w, avail.y});
        ImGui::SetCursorScreenPos(ImVec2(origin.x + w + 12 * k, origin.y));
        if (ImGui::BeginChild("##curve_controls", ImVec2(avail.x - w - 12 * k, avail.y)))
            curve_controls(ctx, id);
        ImGui::EndChild();
        return;
    }
    const float side_h = std::clamp(avail.y * 0.62f, 120 * k, avail.x);
    plane_canvas(ctx, *obj, *c, {origin.x, origin.y, avail.x, side_h});
    ImGui::SetCursorScreenPos(
        ImVec2(origin.x, origin.y + side_h + ImGui::GetStyle().ItemSpacing.y));
    curve_controls(ctx, id);
    (void)cd;
}

} // namespace isoparm::ui
