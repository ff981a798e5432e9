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
#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/curve_glyphs.hpp"
#include "ui/view/text_wrap.hpp"

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
    report_item("curve/osculating");
    same_line_if_fits(toggle_width("Frenet frame"));
    ImGui::Checkbox("Frenet frame", &cd.frenet);
    report_item("curve/frenet");
}

void draw_curve_analysis(const AppContext& ctx, const geom::Curve& c, double t, Picture& pic,
                         const std::function<glm::vec2(const glm::dvec3&)>& px) {
    const CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    const CurveGlyphs g = curve_glyphs(c, t, {cd.comb, cd.osculating, cd.frenet});
    const Rgba8 tooth = rgba8(120, 200, 255, 150), rim = rgba8(120, 200, 255);
    for (const auto& [base, tip] : g.teeth) pic.line(px(base), px(tip), tooth, 1.0f * k);
    std::vector<glm::vec2> tips;
    for (const glm::dvec3& q : g.rim) tips.push_back(px(q));
    pic.polyline(std::move(tips), rim, 1.4f * k);
    if (g.centre) {
        const Rgba8 orange = rgba8(250, 170, 60, 230);
        std::vector<glm::vec2> ring;
        for (const glm::dvec3& q : g.circle) ring.push_back(px(q));
        pic.polyline(std::move(ring), orange, 1.5f * k);
        pic.disk(px(*g.centre), 3 * k, rgba8(250, 170, 60));
        if (const auto p = geom::curve_point(c, t))
            pic.line(px(*p), px(*g.centre), rgba8(250, 170, 60, 120), 1 * k);
    }
    if (g.point) {
        auto arrow = [&](const glm::dvec3& d, Rgba8 col, const char* name) {
            const glm::vec2 a = px(*g.point), b = px(*g.point + d * g.frame_length);
            pic.line(a, b, col, 2.2f * k);
            pic.disk(b, 3 * k, col);
            pic.label(b, name, col, 35);
        };
        arrow(*g.tangent, rgba8(235, 80, 80), "T");
        if (g.normal) arrow(*g.normal, rgba8(90, 210, 90), "N");
        if (g.binormal) arrow(*g.binormal, rgba8(90, 140, 255), "B");
    }
}

void curvature_plot(AppContext& ctx, const geom::Curve& c, const Rect& box) {
    const float k = ctx.ui.scale();
    Picture pic;
    pic.view = "curvature";
    pic.frame = box;
    pic.background = ctx.ui.presentation ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
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
    // Two text lines at the top (kappa, then tau) stay clear of the plot.
    const float line_h = ImGui::GetTextLineHeight();
    const float plot_top = box.y + 2 * line_h + 6 * k;
    auto x_of = [&](double s) {
        return box.x + static_cast<float>((s - d.lo) / std::max(d.hi - d.lo, 1e-300)) * box.w;
    };
    auto y_of = [&](double v) {
        return box.y + box.h - static_cast<float>(v / top) * (box.y + box.h - plot_top - 2);
    };
    std::vector<glm::vec2> line;
    auto flush = [&] {
        pic.polyline(std::move(line), rgba8(120, 200, 255), 1.6f * k);
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
            pic.line({x_of(run.value), box.y}, {x_of(run.value), box.y + box.h},
                     rgba8(150, 150, 160, 90), 1 * k);
    const double t = ctx.ui.curve.trace_param(c);
    pic.line({x_of(t), box.y}, {x_of(t), box.y + box.h}, rgba8(235, 60, 60), 1.2f * k);
    const auto f = geom::curve_curvature(c, t);
    const std::string kappa_text =
        f && f->curvature
            ? "kappa(" + geom::format_short(t, 3) + ") = " + geom::format_short(*f->curvature) +
                  (*f->curvature > 0 ? "" : " (straight here)")
            : "kappa(" + geom::format_short(t, 3) + ") undefined (no tangent)";
    // Each on its own line, shortened with the whole text in its tooltip where the panel is
    // narrow (tau was cut at the edge).
    const Rgba8 text = ImGui::GetColorU32(ImGuiCol_Text);
    const MeasureText measure = imgui_measure();
    const float room = box.w - 8 * k - 4;
    auto add = [&](const std::string& s, float y) {
        LabelRequest& r = pic.fixed_label({box.x + 4 * k, y}, shortened(s, room, measure), text,
                                          LabelAlign::top_left);
        if (r.text != s) r.tooltip = s;
    };
    add(kappa_text, box.y + 2 * k);
    if (f && f->torsion) add("tau = " + geom::format_short(*f->torsion), box.y + 3 * k + line_h);
    draw_picture(pic);
    ImGui::Dummy(ImVec2(box.w, box.h));
}

} // namespace isoparm::ui::curve_designer
