// The curve designer's differential geometry (DesignMentor's second curve system showed the
// moving triad and the curvature circle): the curvature comb, the osculating circle and the
// Frenet frame at t on the canvas, and curvature against t under the basis plot. Every value
// comes from exact derivatives (geom::curve_curvature), never from the polyline.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <vector>

#include "core/geom/curvature.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/flow.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/curve_glyphs.hpp"

namespace isoparm::ui::curve_designer {

void analysis_toggles(AppContext& ctx) {
    CurveDesignerState& cd = ctx.ui.curve;
    ImGui::Checkbox("Comb", &cd.comb);
    report_item("curve/comb");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The curvature comb: a tooth kappa(t) long along -N at each sample;\n"
                          "the teeth's ends show how curvature changes along the curve.");
    same_line_if_fits(toggle_width("Osculating circle"));
    ImGui::Checkbox("Osculating circle", &cd.osculating);
    same_line_if_fits(toggle_width("Frenet frame"));
    ImGui::Checkbox("Frenet frame", &cd.frenet);
}

void draw_curve_analysis(const AppContext& ctx, const geom::Curve& c, double t, ImDrawList* dl,
                         const std::function<ImVec2(const glm::dvec3&)>& px) {
    const CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    const CurveGlyphs g = curve_glyphs(c, t, {cd.comb, cd.osculating, cd.frenet});
    const ImU32 tooth = IM_COL32(120, 200, 255, 150), rim = IM_COL32(120, 200, 255, 255);
    for (const auto& [base, tip] : g.teeth) dl->AddLine(px(base), px(tip), tooth, 1.0f * k);
    std::vector<ImVec2> tips;
    for (const glm::dvec3& q : g.rim) tips.push_back(px(q));
    if (tips.size() > 1)
        dl->AddPolyline(tips.data(), static_cast<int>(tips.size()), rim, 0, 1.4f * k);
    if (g.centre) {
        const ImU32 orange = IM_COL32(250, 170, 60, 230);
        std::vector<ImVec2> ring;
        for (const glm::dvec3& q : g.circle) ring.push_back(px(q));
        dl->AddPolyline(ring.data(), static_cast<int>(ring.size()), orange, 0, 1.5f * k);
        dl->AddCircleFilled(px(*g.centre), 3 * k, IM_COL32(250, 170, 60, 255));
        if (const auto p = geom::curve_point(c, t))
            dl->AddLine(px(*p), px(*g.centre), IM_COL32(250, 170, 60, 120), 1 * k);
    }
    if (g.point) {
        auto arrow = [&](const glm::dvec3& d, ImU32 col, const char* name) {
            const ImVec2 a = px(*g.point), b = px(*g.point + d * g.frame_length);
            dl->AddLine(a, b, col, 2.2f * k);
            dl->AddCircleFilled(b, 3 * k, col);
            dl->AddText(ImVec2(b.x + 4 * k, b.y - 4 * k), col, name);
        };
        arrow(*g.tangent, IM_COL32(235, 80, 80, 255), "T");
        if (g.normal) arrow(*g.normal, IM_COL32(90, 210, 90, 255), "N");
        if (g.binormal) arrow(*g.binormal, IM_COL32(90, 140, 255, 255), "B");
    }
}

void curvature_plot(AppContext& ctx, const geom::Curve& c, const Rect& box) {
    const float k = ctx.ui.scale();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 a(box.x, box.y), b(box.x + box.w, box.y + box.h);
    dl->AddRectFilled(
        a, b, ctx.ui.presentation ? IM_COL32(250, 250, 250, 255) : IM_COL32(26, 28, 34, 255));
    const geom::Interval d = geom::domain(c);
    const std::vector<double> ts = geom::uniform_params(d.lo, d.hi, 240);
    std::vector<double> kappa;
    double top = 0;
    for (double s : ts) {
        const auto f = geom::curve_curvature(c, s);
        kappa.push_back(f && f->curvature ? *f->curvature : std::nan(""));
        if (f && f->curvature) top = std::max(top, *f->curvature);
    }
    top = top > 0 ? top * 1.1 : 1;
    auto x_of = [&](double s) {
        return box.x + static_cast<float>((s - d.lo) / std::max(d.hi - d.lo, 1e-300)) * box.w;
    };
    auto y_of = [&](double v) { return box.y + box.h - static_cast<float>(v / top) * (box.h - 4); };
    std::vector<ImVec2> line;
    auto flush = [&] {
        if (line.size() > 1)
            dl->AddPolyline(line.data(), static_cast<int>(line.size()),
                            IM_COL32(120, 200, 255, 255), 0, 1.6f * k);
        line.clear();
    };
    for (std::size_t q = 0; q < ts.size(); ++q) {
        if (std::isnan(kappa[q])) {
            flush(); // no point or no tangent there: a gap, not a made-up value
            continue;
        }
        line.emplace_back(x_of(ts[q]), y_of(kappa[q]));
    }
    flush();
    // Knots: where the polynomial pieces meet, and where the curvature may jump.
    for (const geom::KnotRun& run : geom::knot_runs(c.knots))
        if (run.value > d.lo && run.value < d.hi)
            dl->AddLine(ImVec2(x_of(run.value), box.y), ImVec2(x_of(run.value), box.y + box.h),
                        IM_COL32(150, 150, 160, 90), 1 * k);
    const double t = trace_param(ctx, c);
    dl->AddLine(ImVec2(x_of(t), box.y), ImVec2(x_of(t), box.y + box.h), IM_COL32(235, 60, 60, 255),
                1.2f * k);
    char text[128];
    const auto f = geom::curve_curvature(c, t);
    if (f && f->curvature)
        std::snprintf(text, sizeof text, "kappa(%.3g) = %.4g%s", t, *f->curvature,
                      f->curvature > 0 ? "" : " (straight here)");
    else
        std::snprintf(text, sizeof text, "kappa(%.3g) undefined (no tangent)", t);
    std::string label = text;
    if (f && f->torsion) {
        std::snprintf(text, sizeof text, ", tau = %.4g", *f->torsion);
        label += text;
    }
    dl->AddText(ImVec2(box.x + 4 * k, box.y + 2 * k), ImGui::GetColorU32(ImGuiCol_Text),
                label.c_str());
    ImGui::Dummy(ImVec2(box.w, box.h));
}

} // namespace isoparm::ui::curve_designer
