// The basis-function panel (partition of unity): for the selected control point, R_ij at
// the indicator, its support as a heat map over the domain, and N_i(u) and N_j(v).
// Every value plotted comes from core (geom::all_basis, geom::rational_basis_ij). A selected
// triangular patch gets B^n_ijk over its domain triangle instead (triangle_basis.cpp).
#include <algorithm>
#include <cmath>
#include <imgui.h>
#include <string>
#include <vector>

#include "core/geom/basis.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/basis_picture.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/mesh_data.hpp"

namespace isoparm::ui {

namespace {

constexpr int heat_resolution = 40;

// Recomputes the heat map only when the basis or the point changed (not while a point is
// dragged: R_ij does not depend on the points' positions).
const HeatMapCache& heat_map(AppContext& ctx, const geom::Surface& s, int i, int j) {
    HeatMapCache& h = ctx.ui.heat;
    if (h.valid && h.i == i && h.j == j && h.resolution == heat_resolution &&
        same_basis(h.surface, s))
        return h;
    const int r = heat_resolution;
    h.values.assign(static_cast<std::size_t>(r * r), 0.f);
    h.max_value = 0;
    const geom::Interval du = geom::domain(s, geom::Dir::u), dv = geom::domain(s, geom::Dir::v);
    for (int row = 0; row < r; ++row)
        for (int c = 0; c < r; ++c) {
            const double u = denormalize_param(du, (c + 0.5) / r);
            const double v = denormalize_param(dv, 1.0 - (row + 0.5) / r);
            const auto value = geom::rational_basis_ij(s, i, j, u, v);
            const float f = value ? static_cast<float>(*value) : std::nanf("");
            h.values[static_cast<std::size_t>(row * r + c)] = f;
            if (value) h.max_value = std::max(h.max_value, std::abs(f));
        }
    h.surface = s;
    h.i = i;
    h.j = j;
    h.resolution = r;
    h.valid = true;
    return h;
}

void heat_canvas(AppContext& ctx, const doc::Object& obj, const geom::Surface& s, int i, int j,
                 const Rect& canvas) {
    const HeatMapCache& h = heat_map(ctx, s, i, j);
    const float k = ctx.ui.scale();
    // Pressing in the map moves the indicator, as in the tracing panel; on the stage the wheel
    // zooms and a right-drag pans.
    ImGui::SetCursorScreenPos(ImVec2(canvas.x, canvas.y));
    ImGui::InvisibleButton("##heat", ImVec2(canvas.w, canvas.h));
    report_item("basis/heat");
    const CanvasView cv = canvas_view(ctx, "basis/heat", canvas);
    const Rect sq = view_rect(cv, canvas, canvas);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Support of %s (white box); largest sampled value %s",
                          point_name('R', i, j, s.n_u, s.n_v).c_str(),
                          geom::format_short(h.max_value).c_str());
    if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        ctx.doc.view.indicator =
            indicator_from_own_domain(ctx.doc, obj, pixel_to_domain(sq, {m.x, m.y}));
    }
    // The drawing (ui/view/basis_picture: the same Picture a figure of the view draws).
    HeatInput in;
    in.canvas = canvas;
    in.square = sq;
    in.values = &h.values;
    in.resolution = h.resolution;
    in.max_value = h.max_value;
    // The support [u_i, u_{i+p+1}] x [v_j, v_{j+q+1}], clipped to the domain.
    const geom::Interval du = geom::domain(s, geom::Dir::u), dv = geom::domain(s, geom::Dir::v);
    auto clamp01 = [](double x) { return std::clamp(x, 0.0, 1.0); };
    in.u0 = clamp01(normalize_param(du, s.knots_u[i]));
    in.u1 = clamp01(normalize_param(du, s.knots_u[i + s.degree_u + 1]));
    in.v0 = clamp01(normalize_param(dv, s.knots_v[j]));
    in.v1 = clamp01(normalize_param(dv, s.knots_v[j + s.degree_v + 1]));
    // The map shows this patch alone: the indicator in its own domain.
    in.at = indicator_in_own_domain(ctx.doc, obj);
    in.name = point_name('R', i, j, s.n_u, s.n_v);
    in.scale = k;
    in.border = ImGui::GetColorU32(ImGuiCol_Border);
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    in.indicator = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 1));
    draw_picture(heat_picture(in));
}

// N_k(t) of every k over the domain (faint) with N_index highlighted, the parameter marked.
void basis_curves(AppContext& ctx, const geom::Knots& U, int p, int n, int index, double t,
                  const std::string& name, const std::string& view, const Rect& box) {
    const float k = ctx.ui.scale();
    const bool light = ctx.ui.presentation;
    ImGui::SetCursorScreenPos(ImVec2(box.x, box.y));
    ImGui::InvisibleButton(("##" + view).c_str(), ImVec2(box.w, box.h));
    report_item("basis/" + view);
    const CanvasView cv = canvas_view(ctx, "basis/" + view, box);
    PlotColors c;
    c.background = light ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
    c.border = ImGui::GetColorU32(ImGuiCol_Border);
    c.faint = light ? rgba8(160, 160, 160) : rgba8(110, 115, 135);
    const doc::Rgba& sc = ctx.doc.colors.selected_point;
    c.strong = ImGui::ColorConvertFloat4ToU32(ImVec4(sc.r, sc.g, sc.b, 1));
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    c.parameter = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 0.9f));
    c.title = ImGui::GetColorU32(ImGuiCol_TextDisabled);
    draw_picture(basis_curves_picture(U, p, n, index, t, name, "basis_" + view, box, cv, k,
                                      ImGui::GetTextLineHeight(), c));
}

} // namespace

void draw_basis_plot_panel(AppContext& ctx) {
    const doc::Object* obj = nullptr;
    const geom::Surface* s =
        teaching_panel_surface(ctx, StageView::basis, draw_triangle_basis, &obj);
    if (!s) return;
    const glm::dvec2 uv = indicator_params(ctx.doc, *obj);
    const bool point = has_valid_point(ctx.doc) && ctx.doc.view.selection.object == obj->id;
    const int i = point ? ctx.doc.view.selection.i : -1, j = point ? ctx.doc.view.selection.j : -1;

    // Partition of unity at the indicator: the sum of the non-zero R_kl.
    const geom::BasisAt bu = geom::basis_at(s->knots_u, s->degree_u, s->n_u, uv.x);
    const geom::BasisAt bv = geom::basis_at(s->knots_v, s->degree_v, s->n_v, uv.y);
    double sum = 0;
    bool exists = true;
    for (int a = 0; a <= s->degree_u && exists; ++a)
        for (int b = 0; b <= s->degree_v; ++b) {
            const auto r =
                geom::rational_basis_ij(*s, bu.first_index + a, bv.first_index + b, uv.x, uv.y);
            if (!r) {
                exists = false;
                break;
            }
            sum += *r;
        }

    if (point) {
        const auto r = geom::rational_basis_ij(*s, i, j, uv.x, uv.y);
        const std::vector<double> nu = geom::all_basis(s->knots_u, s->degree_u, s->n_u, uv.x)[0];
        const std::vector<double> nv = geom::all_basis(s->knots_v, s->degree_v, s->n_v, uv.y)[0];
        const std::string rn = point_name('R', i, j, s->n_u, s->n_v);
        const std::string at =
            rn + "(" + geom::format_short(uv.x) + ", " + geom::format_short(uv.y) + ")";
        if (r)
            text_wrapped("%s = %s", at.c_str(), geom::format_short(*r).c_str());
        else
            text_wrapped("%s undefined (zero denominator)", at.c_str());
        if (r && ImGui::IsItemHovered())
            ImGui::SetTooltip("%s = %s", at.c_str(), geom::format_number(*r).c_str());
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped("N%d(u) = %s   N%d(v) = %s   w = %s", i,
                     geom::format_short(nu[static_cast<std::size_t>(i)]).c_str(), j,
                     geom::format_short(nv[static_cast<std::size_t>(j)]).c_str(),
                     geom::format_short(s->weight(i, j)).c_str());
        ImGui::PopStyleColor();
    } else {
        text_wrapped("Select a control point to see its basis function.");
    }
    // Wrapped: a narrow column must not cut the partition of unity's value.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (exists)
        text_wrapped("Sum of all R_kl at (u, v) = %s", geom::format_short(sum, 7).c_str());
    else
        text_wrapped("S(u,v) does not exist here (zero denominator)");
    ImGui::PopStyleColor();

    const float k = ctx.ui.scale();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const std::string nu_name =
        point ? "N" + std::to_string(i) + "(u), degree " + std::to_string(s->degree_u)
              : "N_k(u), degree " + std::to_string(s->degree_u);
    const std::string nv_name =
        point ? "N" + std::to_string(j) + "(v), degree " + std::to_string(s->degree_v)
              : "N_k(v), degree " + std::to_string(s->degree_v);
    Rect heat, plot_u, plot_v;
    if (on_stage(ctx, StageView::basis)) {
        // On the stage: the map as large as the height allows, the two plots beside it.
        const float side = std::max(std::min(avail.y, avail.x * 0.5f), 40 * k);
        heat = {origin.x, origin.y, side, side};
        const float x = origin.x + side + 12 * k, w = std::max(avail.x - side - 12 * k, 40 * k);
        const float h = std::max((avail.y - spacing) * 0.5f, 40 * k);
        plot_u = {x, origin.y, w, h};
        plot_v = {x, origin.y + h + spacing, w, h};
    } else {
        const float curve_h = std::max(avail.y * 0.2f, 40 * k);
        const float side = std::max(std::min(avail.x, avail.y - 2 * curve_h - 4 * spacing), 40 * k);
        heat = {origin.x, origin.y, side, side};
        const float y = origin.y + side + spacing;
        plot_u = {origin.x, y, avail.x, curve_h};
        plot_v = {origin.x, y + curve_h + spacing, avail.x, curve_h};
    }
    if (point) {
        heat_canvas(ctx, *obj, *s, i, j, heat);
    } else {
        ImGui::SetCursorScreenPos(ImVec2(heat.x, heat.y));
        ImGui::Dummy(ImVec2(heat.w, heat.h));
        ImGui::GetWindowDrawList()->AddRect(ImVec2(heat.x, heat.y),
                                            ImVec2(heat.x + heat.w, heat.y + heat.h),
                                            ImGui::GetColorU32(ImGuiCol_Border));
    }
    basis_curves(ctx, s->knots_u, s->degree_u, s->n_u, i, uv.x, nu_name, "u", plot_u);
    basis_curves(ctx, s->knots_v, s->degree_v, s->n_v, j, uv.y, nv_name, "v", plot_v);
    // Tell ImGui how far the drawing went (for scrolling in a very small panel).
    const float bottom = std::max(heat.y + heat.h, plot_v.y + plot_v.h);
    ImGui::SetCursorScreenPos(ImVec2(origin.x, bottom));
    ImGui::Dummy(ImVec2(1, 1));
}

} // namespace isoparm::ui
