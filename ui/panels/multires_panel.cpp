// The Multires tab: the selected cubic curve or surface as a coarse control polygon (net) at a
// chosen level plus its detail (B-spline wavelets, Finkelstein & Salesin 1994; core/geom/
// multires*.hpp). Dragging a coarse point changes the sweep and keeps the detail; the detail
// buttons change the character and keep the sweep. Every edit is one multires_edit command.
#include <algorithm>
#include <cstdio>
#include <glm/common.hpp>
#include <imgui.h>
#include <string>
#include <variant>
#include <vector>

#include "core/doc/commands_multires.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/multires_edit.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/plane_canvas.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/polygon_hits.hpp"

namespace isoparm::ui {

namespace {

ImVec2 iv(const glm::dvec2& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

// What the canvas shows: the object's own net (fine), the coarse net at the chosen levels,
// and for curves the curve and its sweep (the curve with the detail removed).
struct NetPicture {
    std::vector<glm::dvec3> fine, coarse;
    int fine_nu = 0, fine_nv = 1, nu = 0, nv = 1;
    std::vector<glm::dvec3> curve, sweep;
};

std::vector<glm::dvec3> samples(const geom::Curve& c) {
    const geom::Interval d = geom::domain(c);
    std::vector<glm::dvec3> out;
    for (double t : geom::uniform_params(d.lo, d.hi, 300))
        if (auto p = geom::curve_point(c, t)) out.push_back(*p);
    return out;
}

std::optional<NetPicture> picture(const doc::Object& obj, int level_u, int level_v) {
    NetPicture pic;
    if (const geom::Surface* s = obj.surface()) {
        auto net = geom::multires_coarse_net(*s, level_u, level_v);
        if (!net) return std::nullopt;
        pic.fine = s->points;
        pic.fine_nu = s->n_u;
        pic.fine_nv = s->n_v;
        pic.coarse = std::move(net->points);
        pic.nu = net->n_u;
        pic.nv = net->n_v;
        return pic;
    }
    const geom::Curve& c = *obj.curve();
    auto coarse = geom::multires_coarse_points(c, level_u);
    auto sweep = geom::multires_scale_detail(c, level_u, 0.0);
    if (!coarse || !sweep) return std::nullopt;
    pic.fine = c.points;
    pic.fine_nu = c.count();
    pic.coarse = std::move(coarse).value();
    pic.nu = static_cast<int>(pic.coarse.size());
    pic.curve = samples(c);
    pic.sweep = samples(*sweep);
    return pic;
}

// The rows and columns of an nu x nv net (a curve: nv = 1, one polyline).
void draw_net(ImDrawList* dl, const std::vector<ImVec2>& px, int nu, int nv, ImU32 color,
              float width) {
    std::vector<ImVec2> line;
    for (int j = 0; j < nv; ++j) {
        line.clear();
        for (int i = 0; i < nu; ++i) line.push_back(px[static_cast<std::size_t>(i * nv + j)]);
        dl->AddPolyline(line.data(), nu, color, 0, width);
    }
    if (nv < 2) return;
    for (int i = 0; i < nu; ++i)
        dl->AddPolyline(&px[static_cast<std::size_t>(i * nv)], nv, color, 0, width);
}

int canvas_plane(const AppContext& ctx, const doc::Object& obj) {
    if (const doc::CurveObject* c = obj.curve_object(); c && c->plane != doc::CurvePlane::free3d)
        return curve_designer::canvas_plane(ctx, *c);
    return std::clamp(ctx.ui.multires.plane, 0, 2);
}

void run(AppContext& ctx, doc::MultiresEditSpec spec) {
    if (!ctx.execute(doc::multires_edit(std::move(spec)))) ctx.ui.multires.message = ctx.ui.status;
}

doc::MultiresEditSpec spec_for(const doc::Object& obj, const MultiresState& ms) {
    doc::MultiresEditSpec spec;
    spec.id = obj.id;
    spec.level = ms.level_u;
    if (obj.surface()) spec.level_v = ms.level_v;
    return spec;
}

void canvas(AppContext& ctx, const doc::Object& obj, const Rect& box) {
    MultiresState& ms = ctx.ui.multires;
    const float k = ctx.ui.scale();
    const int plane = canvas_plane(ctx, obj);
    const PlaneAxes ax = plane_axes[plane];
    auto pic = picture(obj, ms.level_u, ms.level_v);
    if (!pic) return;
    auto flat = [&](const glm::dvec3& p) { return glm::dvec2(p[ax.a], p[ax.b]); };
    glm::dvec2 lo = flat(pic->fine[0]), hi = lo;
    for (const auto* set : {&pic->fine, &pic->coarse})
        for (const glm::dvec3& p : *set) {
            lo = glm::min(lo, flat(p));
            hi = glm::max(hi, flat(p));
        }
    const bool same = ms.frame_object == obj.id && ms.frame_plane == plane;
    ms.frame_object = obj.id;
    ms.frame_plane = plane;
    const PlaneMap fitted = kept_frame(ms.frame_lo, ms.frame_hi, same, lo, hi, 0.15, box, 14 * k);
    ImGui::SetCursorScreenPos(ImVec2(box.x, box.y));
    ImGui::InvisibleButton("##multires_canvas", ImVec2(box.w, box.h));
    report_item("multires/canvas");
    // On the stage the wheel zooms and a right-drag pans.
    const PlaneMap map =
        ms.drag >= 0 ? ms.frozen : view_map(canvas_view(ctx, "multires", box), fitted);
    auto px = [&](const glm::dvec3& p) { return iv(plane_to_pixel(map, flat(p))); };
    const ImVec2 m = ImGui::GetIO().MousePos;
    const glm::dvec2 mouse(m.x, m.y);
    std::vector<glm::dvec2> handles;
    for (const glm::dvec3& p : pic->coarse) handles.push_back(plane_to_pixel(map, flat(p)));
    if (ImGui::IsItemActivated() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        ctx.seal();
        ms.message.clear();
        if (const std::optional<int> hit = point_under(handles, mouse, 9 * k)) {
            ms.drag = *hit;
            ms.frozen = map;
            ms.press = mouse;
            ms.grab = mouse - handles[static_cast<std::size_t>(*hit)];
        }
    }
    // A press that has not moved moves nothing (rounding would nudge the point).
    if (ImGui::IsItemActive() && ms.drag >= 0 && ms.drag < static_cast<int>(pic->coarse.size()) &&
        mouse != ms.press) {
        glm::dvec3 to = pic->coarse[static_cast<std::size_t>(ms.drag)];
        const glm::dvec2 ab = pixel_to_plane(ms.frozen, mouse - ms.grab);
        to[ax.a] = ab.x;
        to[ax.b] = ab.y;
        if (to != pic->coarse[static_cast<std::size_t>(ms.drag)]) {
            doc::MultiresEditSpec spec = spec_for(obj, ms);
            spec.i = obj.surface() ? ms.drag / pic->nv : ms.drag;
            spec.j = obj.surface() ? ms.drag % pic->nv : -1;
            spec.position = to;
            run(ctx, spec);
        }
    }
    if (ImGui::IsItemDeactivated() && ms.drag >= 0) {
        ms.drag = -1;
        ctx.seal();
    }

    // Draw what the document holds now (the drag may have changed it).
    const doc::Object* now = ctx.doc.find(obj.id);
    if (!now) return;
    if (auto again = picture(*now, ms.level_u, ms.level_v)) pic = std::move(again);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const bool light = ctx.ui.presentation;
    begin_plane_canvas(dl, map, box, light);
    const doc::Colors& col = ctx.doc.colors;
    std::vector<ImVec2> fine_px, coarse_px;
    for (const glm::dvec3& p : pic->fine) fine_px.push_back(px(p));
    for (const glm::dvec3& p : pic->coarse) coarse_px.push_back(px(p));
    draw_net(dl, fine_px, pic->fine_nu, pic->fine_nv, curve_designer::rgba(col.control_net, 0.45f),
             1.0f * k);
    const ImU32 sweep_col = light ? IM_COL32(40, 110, 200, 255) : IM_COL32(110, 170, 255, 255);
    const ImU32 coarse_col = light ? IM_COL32(170, 30, 170, 255) : IM_COL32(235, 90, 235, 255);
    auto draw_line = [&](const std::vector<glm::dvec3>& line, ImU32 color, float width) {
        std::vector<ImVec2> pts;
        for (const glm::dvec3& p : line) pts.push_back(px(p));
        if (pts.size() > 1)
            dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), color, 0, width * k);
    };
    draw_line(pic->sweep, sweep_col, 2.0f);
    draw_line(pic->curve, curve_designer::rgba(col.selected_surface), 2.4f);
    draw_net(dl, coarse_px, pic->nu, pic->nv, coarse_col, 1.8f * k);
    char name[64];
    for (std::size_t q = 0; q < coarse_px.size(); ++q) {
        const bool held = static_cast<int>(q) == ms.drag;
        dl->AddCircleFilled(coarse_px[q], (held ? 6.0f : 4.5f) * k,
                            held ? curve_designer::rgba(col.selected_point) : coarse_col);
        std::snprintf(name, sizeof name, "multires/coarse/%zu", q);
        report_point(name, coarse_px[q].x, coarse_px[q].y);
    }
    dl->PopClipRect();
}

// The legend under the canvas: what each colour is.
void legend(const AppContext& ctx, bool curve) {
    const bool light = ctx.ui.presentation;
    ImGui::TextColored(light ? ImVec4(0.67f, 0.12f, 0.67f, 1) : ImVec4(0.92f, 0.35f, 0.92f, 1),
                       "coarse (drag)");
    if (!curve) return;
    same_line_if_fits(ImGui::CalcTextSize("sweep").x);
    ImGui::TextColored(light ? ImVec4(0.16f, 0.43f, 0.78f, 1) : ImVec4(0.43f, 0.67f, 1, 1),
                       "sweep");
    if (ImGui::IsItemHovered()) wrapped_tooltip("The curve with every finer detail removed.");
    same_line_if_fits(ImGui::CalcTextSize("curve").x);
    const doc::Rgba& c = ctx.doc.colors.selected_surface;
    ImGui::TextColored(ImVec4(c.r, c.g, c.b, 1), "curve");
}

} // namespace

void draw_multires_panel(AppContext& ctx) {
    note_hovered_view(ctx, StageView::multires);
    MultiresState& ms = ctx.ui.multires;
    const doc::Object* obj = ctx.doc.selected();
    // Curves and surfaces have multiresolution forms (an allow-list: the panel below asks
    // obj->surface() to tell the two apart).
    const bool multires_kind =
        obj && std::visit(doc::overloaded{
                              [](const doc::SurfaceObject&) { return true; },
                              [](const doc::CurveObject&) { return true; },
                              [](const doc::ImplicitObject&) { return false; },
                              [](const doc::TriangleObject&) { return false; },
                          },
                          obj->shape);
    if (!multires_kind) {
        text_wrapped("Select a cubic curve or surface with 2^j + 3 control points and "
                     "clamped uniform knots (5, 7, 11, 19, 35 ... points).");
        return;
    }
    const auto levels = doc::multires_levels_of(*obj);
    if (!levels) {
        text_wrapped("No levels: %s", levels.error().message.c_str());
        return;
    }
    const bool surface = obj->surface() != nullptr;
    const auto [finest_u, finest_v] = *levels;
    if (ms.object != obj->id) {
        // One level below the object's own: the coarse points and one level of detail.
        ms.object = obj->id;
        ms.level_u = std::max(finest_u - 1, 0);
        ms.level_v = std::max(finest_v - 1, 0);
        ms.drag = -1;
        ms.message.clear();
    }
    // After an undo the object may have other levels: show the nearest that exists.
    ms.level_u = std::clamp(ms.level_u, 0, finest_u);
    if (surface) ms.level_v = std::clamp(ms.level_v, 0, finest_v);
    const float k = ctx.ui.scale();

    // Compact rows: a projector's left column leaves the canvas little height.
    char format[64];
    if (surface) {
        const float half = (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x) / 2;
        std::snprintf(format, sizeof format, "u level %%d: %d pts", (1 << ms.level_u) + 3);
        ImGui::SetNextItemWidth(half);
        ImGui::SliderInt("##multires_level_u", &ms.level_u, 0, finest_u, format);
        report_item("multires/level");
        ImGui::SameLine();
        std::snprintf(format, sizeof format, "v level %%d: %d pts", (1 << ms.level_v) + 3);
        ImGui::SetNextItemWidth(half);
        ImGui::SliderInt("##multires_level_v", &ms.level_v, 0, finest_v, format);
        report_item("multires/level_v");
    } else {
        std::snprintf(format, sizeof format, "level %%d of %d: %d coarse points", finest_u,
                      (1 << ms.level_u) + 3);
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x);
        ImGui::SliderInt("##multires_level", &ms.level_u, 0, finest_u, format);
        report_item("multires/level");
    }
    if (ImGui::IsItemHovered())
        wrapped_tooltip("The coarse control points at this level; the detail of every finer "
                        "level is kept when a coarse point is dragged.");
    report_fact("multires/level", ms.level_u);

    // Change the detail, keep the sweep: one command each.
    const struct {
        const char* label;
        const char* report;
        double factor;
        const char* tip;
    } detail_buttons[] = {
        {"x0", "multires/no_detail", 0.0,
         "Remove every detail finer than this level: the sweep alone."},
        {"x0.5", "multires/half_detail", 0.5, "Halve the detail; the coarse points stay."},
        {"x2", "multires/double_detail", 2.0, "Double the detail; the coarse points stay."},
    };
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Detail");
    for (const auto& b : detail_buttons) {
        same_line_if_fits(button_width(b.label));
        if (ImGui::Button(b.label)) {
            doc::MultiresEditSpec spec = spec_for(*obj, ms);
            spec.detail_scale = b.factor;
            ctx.seal();
            run(ctx, spec);
            ctx.seal();
        }
        report_item(b.report);
        if (ImGui::IsItemHovered()) wrapped_tooltip(b.tip);
    }
    if (surface || obj->curve_object()->plane == doc::CurvePlane::free3d) {
        const char* planes[] = {"xy", "xz", "yz"};
        same_line_if_fits(70 * k);
        ImGui::SetNextItemWidth(70 * k);
        ImGui::Combo("##multires_plane", &ms.plane, planes, 3);
    }

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float legend_h = ImGui::GetTextLineHeightWithSpacing();
    // A short panel (a projector's left column) scrolls rather than shrink the canvas away.
    const float h = std::max(avail.y - legend_h, 90 * k);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    canvas(ctx, *obj, {origin.x, origin.y, avail.x, h});
    ImGui::SetCursorScreenPos(ImVec2(origin.x, origin.y + h + ImGui::GetStyle().ItemSpacing.y));
    legend(ctx, !surface);
    if (!ms.message.empty()) ImGui::TextColored(error_text_color(), "%s", ms.message.c_str());
}

void multires_menu_item(AppContext& ctx, bool curve) {
    const doc::Object* sel = ctx.doc.selected();
    std::string why;
    if (!sel || (curve ? !sel->curve_object() : !sel->surface()))
        why = curve ? "Select a curve first." : "Select a surface first.";
    else if (auto levels = doc::multires_levels_of(*sel); !levels)
        why = levels.error().message;
    const char* label = curve ? "Multiresolution editing of the curve" : "Multiresolution editing";
    if (menu_item(label, nullptr, false, why.empty())) ctx.ui.multires.show_tab = true;
    if (!why.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        wrapped_tooltip(why);
}

} // namespace isoparm::ui
