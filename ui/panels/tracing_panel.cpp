// The tracing panel: the domain square with the draggable position indicator (u, v) and
// the u and v knots as ticks labelled with their values and multiplicities.
#include <algorithm>
#include <cstdio>
#include <imgui.h>
#include <string>
#include <vector>

#include "ui/canvas_map.hpp"
#include "ui/doc_access.hpp"
#include "ui/panels/panels.hpp"

namespace isoparm::ui {

namespace {

ImVec2 iv(const glm::dvec2& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

std::string short_number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return buf;
}

std::string knot_vector_text(const geom::Knots& U) {
    // Runs written as value^multiplicity, as the paper writes 0^4 0.5 1^4; long vectors keep
    // their first and last runs around an ellipsis (the ticks show every knot).
    std::vector<std::string> runs;
    std::size_t k = 0;
    while (k < U.size()) {
        std::size_t m = 1;
        while (k + m < U.size() && U[k + m] == U[k]) ++m;
        std::string r = short_number(U[k]);
        if (m > 1) r += "^" + std::to_string(m);
        runs.push_back(r);
        k += m;
    }
    constexpr std::size_t keep = 4;
    std::string s;
    for (std::size_t n = 0; n < runs.size(); ++n) {
        if (runs.size() > 2 * keep + 1 && n == keep) {
            s += " ... ";
            n = runs.size() - keep - 1;
            continue;
        }
        if (!s.empty() && s.back() != ' ') s += "  ";
        s += runs[n];
    }
    return s;
}

struct Palette {
    ImU32 bg, border, grid, tick, text, mult, indicator, cross;
};

Palette palette(const AppContext& ctx) {
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    const doc::Rgba& kc = ctx.doc.colors.knot_curves;
    const bool light = ctx.ui.presentation;
    Palette p;
    p.bg = light ? IM_COL32(250, 250, 250, 255) : IM_COL32(28, 30, 36, 255);
    p.border = light ? IM_COL32(0, 0, 0, 255) : IM_COL32(170, 175, 190, 255);
    p.grid = ImGui::ColorConvertFloat4ToU32(ImVec4(kc.r, kc.g, kc.b, 0.55f));
    p.tick = ImGui::ColorConvertFloat4ToU32(ImVec4(kc.r, kc.g, kc.b, 1));
    p.text = ImGui::GetColorU32(ImGuiCol_Text);
    p.mult = light ? IM_COL32(170, 60, 0, 255) : IM_COL32(255, 190, 90, 255);
    p.indicator = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 1));
    p.cross = ImGui::ColorConvertFloat4ToU32(ImVec4(ic.r, ic.g, ic.b, 0.45f));
    return p;
}

} // namespace

void draw_tracing_panel(AppContext& ctx) {
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(ctx.doc, &obj);
    if (!s) {
        ImGui::TextWrapped("No surface. Use Surface > New Surface... to create one.");
        return;
    }
    const float k = ctx.ui.scale();
    const glm::dvec2 uv = indicator_params(ctx.doc, *s);
    ImGui::Text("%s  (%s, degree %d x %d)", obj->name.c_str(), geom::spline_type_name(s->type),
                s->degree_u, s->degree_v);

    // Room for the v labels on the left and the u labels below the square.
    const float label_w = ImGui::CalcTextSize("0.000").x + 10 * k;
    const float label_h = ImGui::GetTextLineHeight() * 2 + 8 * k;
    const float fields_h =
        ImGui::GetFrameHeightWithSpacing() * 2 + ImGui::GetTextLineHeightWithSpacing() * 3;
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float side =
        std::max(std::min(avail.x - label_w - 12 * k, avail.y - label_h - fields_h), 60.f * k);
    const ImVec2 cur = ImGui::GetCursorScreenPos();
    const Rect sq{cur.x + label_w, cur.y + 6 * k, side, side};

    // The square is one canvas: press anywhere to move the indicator there, then drag.
    ImGui::SetCursorScreenPos(ImVec2(sq.x, sq.y));
    ImGui::InvisibleButton("##domain", ImVec2(sq.w, sq.h));
    if (ImGui::IsItemActive()) {
        const ImVec2 m = ImGui::GetIO().MousePos;
        ctx.doc.indicator = pixel_to_domain(sq, {m.x, m.y}); // view state, not undoable
    }
    ctx.ui.indicator_drag = ImGui::IsItemActive();

    const Palette pal = palette(ctx);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 a(sq.x, sq.y), b(sq.x + sq.w, sq.y + sq.h);
    dl->AddRectFilled(a, b, pal.bg);

    // Knot lines across the square (where the knot curves run) and ticks with labels.
    const std::vector<KnotTick> tu = knot_ticks(s->knots_u, s->degree_u, s->n_u);
    const std::vector<KnotTick> tv = knot_ticks(s->knots_v, s->degree_v, s->n_v);
    const float tick = 7 * k;
    std::vector<double> px_u, px_v;
    for (const KnotTick& t : tu) px_u.push_back(sq.x + t.position * sq.w);
    for (const KnotTick& t : tv) px_v.push_back(sq.y + (1.0 - t.position) * sq.h);
    const std::vector<bool> keep_u = thin_labels(px_u, ImGui::CalcTextSize("0.00").x + 8 * k);
    // v runs upward on screen: thin from the bottom (ascending pixel order reversed).
    std::vector<double> rev_v;
    for (double p : px_v) rev_v.push_back(-p);
    const std::vector<bool> keep_v = thin_labels(rev_v, ImGui::GetTextLineHeight() * 2.1);

    for (std::size_t n = 0; n < tu.size(); ++n) {
        const float x = static_cast<float>(px_u[n]);
        const float w = (1.0f + static_cast<float>(tu[n].multiplicity - 1) * 1.2f) * k;
        if (tu[n].interior) dl->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), pal.grid, w);
        dl->AddLine(ImVec2(x, b.y), ImVec2(x, b.y + tick), pal.tick, 2 * k);
        if (!keep_u[n]) continue;
        const std::string v = short_number(tu[n].value);
        const float tw = ImGui::CalcTextSize(v.c_str()).x;
        dl->AddText(ImVec2(x - tw / 2, b.y + tick + 1), pal.text, v.c_str());
        if (tu[n].multiplicity > 1) {
            const std::string m = "x" + std::to_string(tu[n].multiplicity);
            const float mw = ImGui::CalcTextSize(m.c_str()).x;
            dl->AddText(ImVec2(x - mw / 2, b.y + tick + 1 + ImGui::GetTextLineHeight()), pal.mult,
                        m.c_str());
        }
    }
    for (std::size_t n = 0; n < tv.size(); ++n) {
        const float y = static_cast<float>(px_v[n]);
        const float w = (1.0f + static_cast<float>(tv[n].multiplicity - 1) * 1.2f) * k;
        if (tv[n].interior) dl->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), pal.grid, w);
        dl->AddLine(ImVec2(a.x - tick, y), ImVec2(a.x, y), pal.tick, 2 * k);
        if (!keep_v[n]) continue;
        const std::string v = short_number(tv[n].value);
        const ImVec2 ts = ImGui::CalcTextSize(v.c_str());
        const float lh = ImGui::GetTextLineHeight();
        const bool mult = tv[n].multiplicity > 1;
        const float top = y - (mult ? lh : lh / 2);
        dl->AddText(ImVec2(a.x - tick - 3 * k - ts.x, top), pal.text, v.c_str());
        if (mult) {
            const std::string m = "x" + std::to_string(tv[n].multiplicity);
            const float mw = ImGui::CalcTextSize(m.c_str()).x;
            dl->AddText(ImVec2(a.x - tick - 3 * k - mw, top + lh), pal.mult, m.c_str());
        }
    }
    dl->AddRect(a, b, pal.border, 0, 0, 1.5f * k);
    dl->AddText(
        ImVec2(b.x - ImGui::CalcTextSize("u").x - 4 * k, b.y - ImGui::GetTextLineHeight() - 2 * k),
        pal.text, "u");
    dl->AddText(ImVec2(a.x + 4 * k, a.y + 2 * k), pal.text, "v");

    // The indicator with its two isoparametric lines.
    const ImVec2 ip = iv(domain_to_pixel(sq, ctx.doc.indicator));
    dl->AddLine(ImVec2(ip.x, a.y), ImVec2(ip.x, b.y), pal.cross, 1.5f * k);
    dl->AddLine(ImVec2(a.x, ip.y), ImVec2(b.x, ip.y), pal.cross, 1.5f * k);
    dl->AddCircleFilled(ip, 7 * k, pal.indicator, 24);
    dl->AddCircle(ip, 7 * k, IM_COL32(0, 0, 0, 255), 24, 1.5f * k);

    // Exact values, in the surface's own parameters.
    ImGui::SetCursorScreenPos(ImVec2(cur.x, b.y + label_h));
    const geom::Interval du = domain_u(*s), dv = domain_v(*s);
    double u = uv.x, v = uv.y;
    ImGui::SetNextItemWidth(std::min(avail.x * 0.4f, 140 * k));
    if (ImGui::InputDouble("u", &u, 0.01, 0.1, "%.4f"))
        ctx.doc.indicator.x = std::clamp(normalize_param(du, u), 0.0, 1.0);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(std::min(avail.x * 0.4f, 140 * k));
    if (ImGui::InputDouble("v", &v, 0.01, 0.1, "%.4f"))
        ctx.doc.indicator.y = std::clamp(normalize_param(dv, v), 0.0, 1.0);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("knots u: %s", knot_vector_text(s->knots_u).c_str());
    ImGui::TextWrapped("knots v: %s", knot_vector_text(s->knots_v).c_str());
    ImGui::PopStyleColor();
}

} // namespace isoparm::ui
