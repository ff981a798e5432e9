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
#include "core/geom/tessellate.hpp"
#include "ui/panels/heat_color.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/triangle_panels.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/mesh_data.hpp"

namespace isoparm::ui {

namespace {

constexpr int heat_resolution = 40;
constexpr int curve_samples = 161;

ImVec2 iv(const glm::dvec2& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

// Recomputes the heat map only when the surface or the point changed.
const HeatMapCache& heat_map(AppContext& ctx, const geom::Surface& s, int i, int j) {
    HeatMapCache& h = ctx.ui.heat;
    if (h.valid && h.i == i && h.j == j && h.resolution == heat_resolution &&
        same_surface(h.surface, s))
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
                 const Rect& sq) {
    const HeatMapCache& h = heat_map(ctx, s, i, j);
    const float k = ctx.ui.scale();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const int r = h.resolution;
    const float cw = sq.w / static_cast<float>(r), ch = sq.h / static_cast<float>(r);
    for (int row = 0; row < r; ++row)
        for (int c = 0; c < r; ++c) {
            const float v = h.values[static_cast<std::size_t>(row * r + c)];
            const ImVec2 a(sq.x + static_cast<float>(c) * cw, sq.y + static_cast<float>(row) * ch);
            const ImU32 col = std::isnan(v) ? IM_COL32(90, 90, 90, 255)
                                            : heat_color(h.max_value > 0 ? v / h.max_value : 0.f);
            dl->AddRectFilled(a, ImVec2(a.x + cw + 0.5f, a.y + ch + 0.5f), col);
        }
    // The support [u_i, u_{i+p+1}] x [v_j, v_{j+q+1}], clipped to the domain.
    const geom::Interval du = geom::domain(s, geom::Dir::u), dv = geom::domain(s, geom::Dir::v);
    auto clamp01 = [](double x) { return std::clamp(x, 0.0, 1.0); };
    const double u0 = clamp01(normalize_param(du, s.knots_u[i]));
    const double u1 = clamp01(normalize_param(du, s.knots_u[i + s.degree_u + 1]));
    const double v0 = clamp01(normalize_param(dv, s.knots_v[j]));
    const double v1 = clamp01(normalize_param(dv, s.knots_v[j + s.degree_v + 1]));
    dl->AddRect(iv(domain_to_pixel(sq, {u0, v1})), iv(domain_to_pixel(sq, {u1, v0})),
                IM_COL32(255, 255, 255, 230), 0, 0, 1.5f * k);
    dl->AddRect(ImVec2(sq.x, sq.y), ImVec2(sq.x + sq.w, sq.y + sq.h),
                ImGui::GetColorU32(ImGuiCol_Border), 0, 0, k);
    // The indicator.
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    // The map shows this patch alone: the indicator in its own domain.
    const ImVec2 p = iv(domain_to_pixel(sq, indicator_in_own_domain(ctx.doc, obj)));
    dl->AddCircleFilled(p, 5 * k, ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 1)), 16);
    dl->AddCircle(p, 5 * k, IM_COL32(0, 0, 0, 255), 16, 1.2f * k);
    ImGui::SetCursorScreenPos(ImVec2(sq.x, sq.y));
    ImGui::InvisibleButton("##heat", ImVec2(sq.w, sq.h));
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Support of %s (white box); max %.3g",
                          point_name('R', i, j, s.n_u, s.n_v).c_str(), h.max_value);
    // Pressing in the map moves the indicator, as in the tracing panel.
    if (ImGui::IsItemActive()) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        ctx.doc.view.indicator =
            indicator_from_own_domain(ctx.doc, obj, pixel_to_domain(sq, {m.x, m.y}));
    }
}

// N_k(t) of every k over the domain (faint) with N_index highlighted, the parameter marked.
void basis_curves(const AppContext& ctx, const geom::Knots& U, int p, int n, int index, double t,
                  const char* name, const Rect& box) {
    const float k = ctx.ui.scale();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const bool light = ctx.ui.presentation;
    dl->AddRectFilled(ImVec2(box.x, box.y), ImVec2(box.x + box.w, box.y + box.h),
                      light ? IM_COL32(250, 250, 250, 255) : IM_COL32(26, 28, 34, 255));
    const geom::Interval d = geom::Interval{U[p], U[n]};
    const std::vector<double> ts = geom::uniform_params(d.lo, d.hi, curve_samples);
    std::vector<std::vector<double>> values; // values[sample][k]
    values.reserve(ts.size());
    for (double x : ts) values.push_back(geom::all_basis(U, p, n, x)[0]);
    const float top = box.y + 4 * k, h = box.h - 8 * k;
    auto pt = [&](std::size_t sample, double y) {
        return ImVec2(box.x +
                          box.w * static_cast<float>(sample) / static_cast<float>(ts.size() - 1),
                      top + h * (1.f - static_cast<float>(y)));
    };
    const ImU32 faint = light ? IM_COL32(160, 160, 160, 255) : IM_COL32(110, 115, 135, 255);
    const doc::Rgba& sc = ctx.doc.colors.selected_point;
    const ImU32 strong = ImGui::ColorConvertFloat4ToU32(ImVec4(sc.r, sc.g, sc.b, 1));
    std::vector<ImVec2> line(ts.size());
    auto curve = [&](int f, ImU32 color, float width) {
        for (std::size_t s = 0; s < ts.size(); ++s)
            line[s] = pt(s, values[s][static_cast<std::size_t>(f)]);
        dl->AddPolyline(line.data(), static_cast<int>(line.size()), color, 0, width);
    };
    for (int f = 0; f < n; ++f)
        if (f != index) curve(f, faint, 1 * k);
    if (index >= 0) curve(index, strong, 2.5f * k);
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    const float x = box.x + box.w * static_cast<float>(normalize_param(d, t));
    dl->AddLine(ImVec2(x, box.y), ImVec2(x, box.y + box.h),
                ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 0.9f)), 1.5f * k);
    dl->AddText(ImVec2(box.x + 4 * k, box.y + 2 * k), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                name);
    dl->AddRect(ImVec2(box.x, box.y), ImVec2(box.x + box.w, box.y + box.h),
                ImGui::GetColorU32(ImGuiCol_Border), 0, 0, k);
}

} // namespace

void draw_basis_plot_panel(AppContext& ctx) {
    // A selected triangular patch has its own version of the panel (Farin ch. 17).
    const doc::Object* triangle = nullptr;
    if (const geom::TrianglePatch* t = selected_triangle(ctx.doc, &triangle)) {
        draw_triangle_basis(ctx, *triangle, *t);
        return;
    }
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(ctx.doc, &obj);
    if (!s) {
        ImGui::TextWrapped("No surface.");
        return;
    }
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
        if (r)
            ImGui::TextWrapped("%s(%.3f, %.3f) = %.5f", rn.c_str(), uv.x, uv.y, *r);
        else
            ImGui::TextWrapped("%s(%.3f, %.3f) undefined (zero denominator)", rn.c_str(), uv.x,
                               uv.y);
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("N%d(u) = %.4f   N%d(v) = %.4f   w = %.4g", i,
                           nu[static_cast<std::size_t>(i)], j, nv[static_cast<std::size_t>(j)],
                           s->weight(i, j));
        ImGui::PopStyleColor();
    } else {
        ImGui::TextWrapped("Select a control point to see its basis function.");
    }
    // Wrapped: a narrow column must not cut the partition of unity's value.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (exists)
        ImGui::TextWrapped("Sum of all R_kl at (u,v) = %.6f", sum);
    else
        ImGui::TextWrapped("S(u,v) does not exist here (zero denominator)");
    ImGui::PopStyleColor();

    const float k = ctx.ui.scale();
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float curve_h = std::max(avail.y * 0.2f, 40 * k);
    const float spacing = ImGui::GetStyle().ItemSpacing.y;
    const float side = std::max(std::min(avail.x, avail.y - 2 * curve_h - 4 * spacing), 40 * k);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    if (point) {
        heat_canvas(ctx, *obj, *s, i, j, {origin.x, origin.y, side, side});
    } else {
        ImGui::Dummy(ImVec2(side, side));
        ImGui::GetWindowDrawList()->AddRect(origin, ImVec2(origin.x + side, origin.y + side),
                                            ImGui::GetColorU32(ImGuiCol_Border));
    }
    const float y = origin.y + side + spacing;
    const std::string nu_name =
        point ? "N" + std::to_string(i) + "(u), degree " + std::to_string(s->degree_u)
              : "N_k(u), degree " + std::to_string(s->degree_u);
    const std::string nv_name =
        point ? "N" + std::to_string(j) + "(v), degree " + std::to_string(s->degree_v)
              : "N_k(v), degree " + std::to_string(s->degree_v);
    basis_curves(ctx, s->knots_u, s->degree_u, s->n_u, i, uv.x, nu_name.c_str(),
                 {origin.x, y, avail.x, curve_h});
    basis_curves(ctx, s->knots_v, s->degree_v, s->n_v, j, uv.y, nv_name.c_str(),
                 {origin.x, y + curve_h + spacing, avail.x, curve_h});
    // Tell ImGui how far the drawing went (for scrolling in a very small panel).
    ImGui::SetCursorScreenPos(ImVec2(origin.x, y + curve_h + spacing));
    ImGui::Dummy(ImVec2(1, curve_h));
}

} // namespace isoparm::ui
