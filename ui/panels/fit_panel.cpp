// The Fit panel: data points clicked on a plane canvas or loaded from a CSV / XYZ file, the
// fitted curve (interpolation or least squares) or surface (a grid) drawn over them with a
// whisker from every point to where the fit passes, the largest and RMS distance, and Add to
// scene (one undo step).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <imgui.h>

#include "core/doc/commands.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "core/scene/point_file.hpp"
#include "ui/actions.hpp"
#include "ui/fit_actions.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/enum_combo.hpp"
#include "ui/panels/fit_panel.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/plane_canvas.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/text_wrap.hpp"

namespace isoparm::ui {

namespace {

using curve_designer::rgba;

ImVec2 iv(const glm::dvec2& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

// Refits when the points or the settings changed; a refusal is kept for the panel.
void refit(FitState& f) {
    if (!f.stale) return;
    f.stale = false;
    f.fit.reset();
    f.error.clear();
    if (f.points.empty()) return;
    geom::Expected<doc::Fit> r =
        f.rows > 1 ? doc::fit_grid(f.points, f.rows, f.columns, f.settings, "fit")
                   : doc::fit_curve(f.points, f.settings, "fit", doc::CurvePlane::xy);
    if (r)
        f.fit = std::move(r).value();
    else
        f.error = r.error().message;
}

// The framing: the data's box in the canvas plane with room around it (an empty canvas shows
// [-2, 2]^2), kept while every point stays inside it so that a click does not shift the
// picture under the mouse; it grows when a point leaves it, and starts again with a new plane
// or new data.
PlaneMap frame(FitState& f, const Rect& canvas, const PlaneAxes& ax, float margin) {
    glm::dvec2 lo(-2), hi(2);
    if (!f.points.empty()) {
        lo = hi = glm::dvec2(f.points[0][ax.a], f.points[0][ax.b]);
        for (const glm::dvec3& p : f.points) {
            lo = glm::min(lo, glm::dvec2(p[ax.a], p[ax.b]));
            hi = glm::max(hi, glm::dvec2(p[ax.a], p[ax.b]));
        }
    }
    const bool same = f.frame_plane == f.plane;
    f.frame_plane = f.plane;
    return kept_frame(f.frame_lo, f.frame_hi, same, lo, hi, 0.15, canvas, margin);
}

int nearest_point(const FitState& f, const PlaneMap& map, const PlaneAxes& ax,
                  const glm::dvec2& mouse, double radius) {
    int best = -1;
    double best_d = radius;
    for (std::size_t k = 0; k < f.points.size(); ++k) {
        const glm::dvec3& p = f.points[k];
        const double d = glm::distance(plane_to_pixel(map, {p[ax.a], p[ax.b]}), mouse);
        if (d <= best_d) best = static_cast<int>(k), best_d = d;
    }
    return best;
}

// Clicks add a point (appended: the fit follows the order of the points), a drag moves one,
// a right click deletes the nearest. A loaded grid is only looked at here.
void canvas(AppContext& ctx, const Rect& r) {
    FitState& f = ctx.ui.fit;
    const PlaneAxes ax = plane_axes[f.plane];
    const float k = ctx.ui.scale();
    const PlaneMap map = f.drag >= 0 ? f.frozen : frame(f, r, ax, 12 * k);
    ImGui::SetCursorScreenPos(ImVec2(r.x, r.y));
    ImGui::InvisibleButton("##fit_canvas", ImVec2(r.w, r.h),
                           ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    report_item("fit/canvas");
    const ImVec2 m = ImGui::GetIO().MousePos;
    const glm::dvec2 mouse(m.x, m.y);
    const bool editable = f.rows <= 1;
    if (editable && ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        f.drag = nearest_point(f, map, ax, mouse, 7 * k);
        if (f.drag < 0) {
            glm::dvec3 p(0);
            const glm::dvec2 ab = pixel_to_plane(map, mouse);
            p[ax.a] = ab.x;
            p[ax.b] = ab.y;
            f.points.push_back(p);
            f.source.clear();
            f.stale = true;
        }
        f.frozen = map;
    }
    if (editable && ImGui::IsItemActive() && f.drag >= 0 &&
        f.drag < static_cast<int>(f.points.size())) {
        const glm::dvec2 ab = pixel_to_plane(f.frozen, mouse);
        glm::dvec3& p = f.points[static_cast<std::size_t>(f.drag)];
        if (p[ax.a] != ab.x || p[ax.b] != ab.y) {
            p[ax.a] = ab.x;
            p[ax.b] = ab.y;
            f.stale = true;
        }
    }
    if (ImGui::IsItemDeactivated()) f.drag = -1;
    if (editable && ImGui::IsItemHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
        if (const int hit = nearest_point(f, map, ax, mouse, 9 * k); hit >= 0) {
            f.points.erase(f.points.begin() + hit);
            f.stale = true;
        }
    }
    refit(f);

    ImDrawList* dl = ImGui::GetWindowDrawList();
    const bool light = ctx.ui.presentation;
    begin_plane_canvas(dl, map, r, light);
    auto px = [&](const glm::dvec3& p) { return iv(plane_to_pixel(map, {p[ax.a], p[ax.b]})); };
    const doc::Colors& col = ctx.doc.colors;
    const ImU32 fit_col = rgba(col.selected_surface);
    if (f.fit) {
        if (const doc::CurveObject* c = f.fit->object.curve_object()) {
            const geom::Interval d = geom::domain(c->curve);
            std::vector<ImVec2> line;
            for (double t : geom::uniform_params(d.lo, d.hi, 401))
                if (const auto p = geom::curve_point(c->curve, t)) line.push_back(px(*p));
            dl->AddPolyline(line.data(), static_cast<int>(line.size()), fit_col, 0, 2.2f * k);
        } else if (const geom::Surface* s = f.fit->object.surface()) {
            // The isocurves through the data: u_k of the rows, v_l of the columns.
            const auto [u0, u1] = geom::domain(*s, geom::Dir::u);
            const auto [v0, v1] = geom::domain(*s, geom::Dir::v);
            const std::size_t nu = static_cast<std::size_t>(f.rows);
            for (std::size_t q = 0; q < f.fit->params.size(); ++q) {
                const bool along_v = q < nu;
                const double c = f.fit->params[q];
                std::vector<ImVec2> line;
                for (double t : geom::uniform_params(along_v ? v0 : u0, along_v ? v1 : u1, 101))
                    if (const auto p =
                            along_v ? geom::surface_point(*s, c, t) : geom::surface_point(*s, t, c))
                        line.push_back(px(*p));
                dl->AddPolyline(line.data(), static_cast<int>(line.size()), fit_col, 0, 1.4f * k);
            }
        }
        // Whiskers: from every data point to where the fit passes at its parameter.
        const ImU32 whisker = light ? IM_COL32(200, 30, 30, 255) : IM_COL32(255, 90, 90, 255);
        for (std::size_t q = 0; q < f.points.size() && q < f.fit->on_result.size(); ++q)
            dl->AddLine(px(f.points[q]), px(f.fit->on_result[q]), whisker, 1.6f * k);
    }
    const ImU32 point_col = rgba(col.control_points);
    for (std::size_t q = 0; q < f.points.size(); ++q) {
        const ImVec2 c = px(f.points[q]);
        dl->AddCircleFilled(c, (static_cast<int>(q) == f.drag ? 5.0f : 3.5f) * k, point_col);
        if (f.points.size() <= 60) report_point("fit/point/" + std::to_string(q), c.x, c.y);
    }
    dl->PopClipRect();
    if (f.points.empty()) {
        // The hint through the label placer, shortened to the canvas (the whole in a tooltip).
        Picture pic;
        pic.view = "fit";
        pic.frame = r;
        const std::string hint = "Click to add data points, in order; right click deletes one";
        LabelRequest& l = pic.fixed_label(
            {r.x + 8 * k, r.y + 6 * k}, shortened(hint, r.w - 16 * k, imgui_measure()),
            light ? IM_COL32(90, 90, 90, 255) : IM_COL32(150, 150, 160, 255), LabelAlign::top_left);
        if (l.text != hint) l.tooltip = hint;
        draw_picture(pic, dl);
    }
}

void settings(AppContext& ctx) {
    FitState& f = ctx.ui.fit;
    doc::FitSettings& s = f.settings;
    const float w = 90 * ctx.ui.scale();
    bool changed = false;
    const bool grid = f.rows > 1;
    {
        // Two choices, both in view: a radio pair rather than a combo.
        for (const auto& m : doc::fit_method_names) {
            if (m.value != doc::FitMethod::interpolate) same_line_if_fits(toggle_width(m.label));
            if (ImGui::RadioButton(m.label, s.method == m.value)) {
                changed |= s.method != m.value;
                s.method = m.value;
            }
            report_item(std::string("fit/method/") + m.name);
            if (ImGui::IsItemHovered())
                wrapped_tooltip(m.value == doc::FitMethod::interpolate
                                    ? "Through every point (Piegl & Tiller A9.1): as many "
                                      "control points as data points."
                                    : "Near the points (Piegl & Tiller 9.4.1): fewer control "
                                      "points, the sum of squared distances smallest; the ends "
                                      "are kept.");
        }
    }
    ImGui::SetNextItemWidth(w);
    changed |= ImGui::InputInt(grid ? "u-degree" : "Degree", &s.degree);
    if (grid) {
        same_line_if_fits(w + ImGui::CalcTextSize("v-degree").x + 8 * ctx.ui.scale());
        ImGui::SetNextItemWidth(w);
        changed |= ImGui::InputInt("v-degree", &s.degree_v);
        if (s.method == doc::FitMethod::approximate) {
            ImGui::SetNextItemWidth(w);
            changed |= ImGui::InputInt("u points", &s.count);
            same_line_if_fits(w + ImGui::CalcTextSize("v points").x + 8 * ctx.ui.scale());
            ImGui::SetNextItemWidth(w);
            changed |= ImGui::InputInt("v points", &s.count_v);
        }
    } else if (s.method == doc::FitMethod::approximate) {
        same_line_if_fits(w + ImGui::CalcTextSize("Control points").x + 8 * ctx.ui.scale());
        ImGui::SetNextItemWidth(w);
        changed |= ImGui::InputInt("Control points", &s.count);
    }
    ImGui::SetNextItemWidth(std::min(150 * ctx.ui.scale(), ImGui::GetContentRegionAvail().x -
                                                               ImGui::CalcTextSize("Parameters").x -
                                                               8 * ctx.ui.scale()));
    changed |= enum_combo("Parameters", s.parametrization);
    if (changed) f.stale = true;
}

void summary(AppContext& ctx) {
    FitState& f = ctx.ui.fit;
    if (!f.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, error_text_color());
        text_wrapped("Not fitted: %s", f.error.c_str());
        ImGui::PopStyleColor();
        return;
    }
    if (!f.fit) return;
    // Where the data came from, then how near the fit is: two short lines in a narrow panel.
    const std::string data =
        f.rows > 1 ? std::to_string(f.rows) + " x " + std::to_string(f.columns) + " grid"
                   : std::to_string(f.points.size()) + " points";
    const std::string from = f.source.empty() ? "" : " (" + f.source + ")";
    if (f.settings.method == doc::FitMethod::interpolate)
        text_wrapped("%s%s: through every one (largest distance %.2g).", data.c_str(), from.c_str(),
                     f.fit->max_error);
    else
        text_wrapped("%s%s: largest distance %.4g, RMS %.4g (red whiskers); %s kept.", data.c_str(),
                     from.c_str(), f.fit->max_error, f.fit->rms_error,
                     f.rows > 1 ? "corners" : "ends");
    report_fact("fit/max_error", f.fit->max_error);
    report_fact("fit/rms_error", f.fit->rms_error);
}

void add_to_scene(AppContext& ctx) {
    FitState& f = ctx.ui.fit;
    if (!f.fit) return;
    doc::Object o = f.fit->object;
    o.name = fresh_name(ctx.doc, f.rows > 1 ? "fitted surface" : "fitted curve");
    if (auto* c = std::get_if<doc::CurveObject>(&o.shape)) {
        // In the canvas plane when every point lies in it, else a 3D curve.
        const int off = 3 - plane_axes[f.plane].a - plane_axes[f.plane].b;
        const bool flat = std::all_of(f.points.begin(), f.points.end(),
                                      [&](const glm::dvec3& p) { return p[off] == 0; });
        c->plane = flat ? static_cast<doc::CurvePlane>(f.plane) : doc::CurvePlane::free3d;
    }
    const std::string name = o.name;
    ctx.seal();
    if (ctx.execute(doc::add_object(std::move(o)))) {
        ctx.doc.view.selection = {ctx.doc.objects.back().id, -1, -1};
        ctx.ui.status = "Added '" + name + "' (Edit > Undo takes it back).";
    }
    ctx.seal();
}

} // namespace

void draw_fit_panel(AppContext& ctx) {
    FitState& f = ctx.ui.fit;
    const float k = ctx.ui.scale();
    for (int p = 0; p < 3; ++p) {
        if (p) same_line_if_fits(toggle_width(plane_axes[p].name));
        ImGui::RadioButton(plane_axes[p].name, &f.plane, p);
    }
    settings(ctx);
    refit(f);
    // The canvas, then a summary of fixed height and the buttons: nothing above the canvas
    // changes height while points are clicked, and a projector's short panel still shows every
    // button (the canvas gives way first).
    const float line = ImGui::GetTextLineHeightWithSpacing();
    const float summary_h = line * 3;
    const float reserved =
        summary_h + ImGui::GetFrameHeightWithSpacing() * 2 + ImGui::GetStyle().ItemSpacing.y * 2;
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float h = std::clamp(avail.y - reserved, 70 * k, std::max(avail.x * 1.2f, 70 * k));
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    canvas(ctx, {origin.x, origin.y, avail.x, h});
    ImGui::SetCursorScreenPos(ImVec2(origin.x, origin.y + h + ImGui::GetStyle().ItemSpacing.y));
    ImGui::BeginChild("##fit_summary", ImVec2(avail.x, summary_h));
    summary(ctx);
    ImGui::EndChild();
    if (ImGui::Button("Load...")) request_load_points_dialog(ctx);
    if (ImGui::IsItemHovered())
        wrapped_tooltip("Points from a CSV or XYZ file: x y or x y z a line; blank lines between "
                        "the rows of a grid make a surface.");
    report_item("fit/load");
    same_line_if_fits(button_width("Clear"));
    if (ImGui::Button("Clear")) {
        // The points go; the plane and the settings stay.
        FitState cleared;
        cleared.open = true;
        cleared.plane = f.plane;
        cleared.settings = f.settings;
        f = std::move(cleared);
    }
    same_line_if_fits(button_width("Add to scene"));
    ImGui::BeginDisabled(!f.fit);
    if (ImGui::Button("Add to scene")) add_to_scene(ctx);
    ImGui::EndDisabled();
    report_item("fit/add");
    same_line_if_fits(button_width("Close"));
    if (ImGui::Button("Close")) f.open = false;
    report_item("fit/close");
}

} // namespace isoparm::ui
