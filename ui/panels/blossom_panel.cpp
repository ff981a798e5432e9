// The Blossom tab (Ramshaw's polar forms; Farin ch. 4; core/geom/blossom.hpp): for the piece of
// the selected curve at the designer's t, every point of de Boor's triangle labelled with its
// blossom arguments, p sliders for f(a_1, ..., a_p) and buttons that set them to the diagonal
// (the curve point) or to a control point's consecutive knots. For a surface, the u- and
// v-stages at the indicator listed the same way, with sliders for f(u-args; v-args).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <imgui.h>
#include <string>
#include <vector>

#include "core/geom/blossom.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

// "f(0.25, t, t)" with `t` written as the symbol where an argument is the trace parameter.
std::string polar_text(const std::vector<double>& args, double t, const char* symbol) {
    std::string s = "f(";
    for (std::size_t k = 0; k < args.size(); ++k) {
        if (k) s += ", ";
        if (symbol && args[k] == t) {
            s += symbol;
        } else {
            s += geom::format_short(args[k], 3);
        }
    }
    return s + ")";
}

// "f(u, u, 0.5; v, 0.25)": a surface point's u- and v-arguments.
std::string surface_polar_text(const std::vector<double>& u_args, const std::vector<double>& v_args,
                               const glm::dvec2& uv, bool symbols) {
    std::string u = polar_text(u_args, uv.x, symbols ? "u" : nullptr);
    u.pop_back(); // the ")"
    return u + "; " + polar_text(v_args, uv.y, symbols ? "v" : nullptr).substr(2);
}

std::string point_text(const std::optional<glm::dvec3>& p) {
    if (!p) return "at infinity (weight 0)";
    return "(" + geom::format_short(p->x) + ", " + geom::format_short(p->y) + ", " +
           geom::format_short(p->z) + ")";
}

// The arguments' range on a piece: the knots its control points' labels use.
struct ArgumentRange {
    double lo = 0, hi = 1;
};
ArgumentRange argument_range(const geom::Knots& U, int p, int span) {
    return {U[static_cast<std::size_t>(span - p + 1)], U[static_cast<std::size_t>(span + p)]};
}

// Keeps `args` for this piece: new (the diagonal at t) when the object, piece or degree changed.
void keep_arguments(std::vector<double>& args, std::uint64_t& key_object, int& key_span,
                    std::uint64_t object, int span, int p, double t) {
    if (key_object == object && key_span == span && static_cast<int>(args.size()) == p) return;
    key_object = object;
    key_span = span;
    args.assign(static_cast<std::size_t>(p), t);
}

// p sliders on one row, each over the piece's argument range ("a1 0.375"); true when one moved.
bool argument_sliders(std::vector<double>& args, const ArgumentRange& r, const char* prefix) {
    bool moved = false;
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const float width = (ImGui::GetContentRegionAvail().x - spacing * (args.size() - 1.0f)) /
                        static_cast<float>(args.size());
    char label[32], format[32];
    for (std::size_t k = 0; k < args.size(); ++k) {
        if (k) ImGui::SameLine();
        std::snprintf(label, sizeof label, "##%s%zu", prefix, k + 1);
        std::snprintf(format, sizeof format, "%s%zu %%.3f", prefix, k + 1);
        ImGui::SetNextItemWidth(width);
        moved |= ImGui::SliderScalar(label, ImGuiDataType_Double, &args[k], &r.lo, &r.hi, format);
        report_item(std::string("blossom/") + (label + 2));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Between %.4g and %.4g: the knots this piece's control points use",
                              r.lo, r.hi);
    }
    return moved;
}

// Whether the arguments are a permutation of `labels` (the blossom is symmetric).
bool same_arguments(std::vector<double> a, std::vector<double> b) {
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (std::abs(a[k] - b[k]) > 1e-12 * std::max(1.0, std::abs(b[k]))) return false;
    return true;
}

void curve_canvas(AppContext& ctx, const doc::CurveObject& c, const geom::DeBoorTriangle& at_t,
                  const geom::DeBoorTriangle& at_args, double t, const Rect& box) {
    const geom::Curve& g = c.curve;
    const PlaneAxes ax = plane_axes[curve_designer::canvas_plane(ctx, c)];
    const float k = ctx.ui.scale();
    auto flat = [&](const glm::dvec3& p) { return glm::dvec2(p[ax.a], p[ax.b]); };
    // Framed on the piece: its control points and the sliders' triangle.
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const auto* tri : {&at_t, &at_args})
        for (const auto& level : tri->levels)
            for (const geom::HPoint& h : level)
                if (auto p = geom::DeBoorTriangle::cartesian(h)) {
                    lo = glm::min(lo, flat(*p));
                    hi = glm::max(hi, flat(*p));
                }
    if (lo.x > hi.x) lo = hi = glm::dvec2(0);
    const glm::dvec2 pad = glm::max((hi - lo) * 0.2, glm::dvec2(0.05));
    ImGui::SetCursorScreenPos(ImVec2(box.x, box.y));
    ImGui::InvisibleButton("##blossom_canvas", ImVec2(std::max(box.w, 1.f), std::max(box.h, 1.f)));
    report_item("blossom/canvas");
    const PlaneMap map =
        view_map(canvas_view(ctx, "blossom", box), fit_plane(box, lo - pad, hi + pad, 10 * k));
    auto px = [&](const glm::dvec3& p) { return glm::vec2(plane_to_pixel(map, flat(p))); };
    const bool light = ctx.ui.presentation;
    Picture pic;
    pic.view = "blossom";
    pic.frame = box;
    pic.background = light ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
    pic.style.offset = 5 * k;
    const glm::dvec2 o = plane_to_pixel(map, {0, 0});
    const Rgba8 axis_col = light ? rgba8(150, 150, 150) : rgba8(80, 84, 96);
    pic.line({box.x, static_cast<float>(o.y)}, {box.x + box.w, static_cast<float>(o.y)}, axis_col);
    pic.line({static_cast<float>(o.x), box.y}, {static_cast<float>(o.x), box.y + box.h}, axis_col);
    const doc::Colors& col = ctx.doc.colors;
    std::vector<glm::vec2> line;
    for (const glm::dvec3& p : g.points) line.push_back(px(p));
    pic.polyline(std::move(line), curve_designer::rgba(col.control_net, 0.4f), 1.0f * k);
    line.clear();
    const geom::Interval d = geom::domain(g);
    for (double s : geom::uniform_params(d.lo, d.hi, 300))
        if (auto p = geom::curve_point(g, s)) line.push_back(px(*p));
    pic.polyline(std::move(line), curve_designer::rgba(col.selected_surface), 2.0f * k);

    // de Boor's triangle at t, labelled with its blossom arguments, level by level; the placer
    // keeps the labels apart (the last levels, nearest the curve point, matter most).
    const Rgba8 text_col = light ? rgba8(20, 20, 20) : rgba8(230, 230, 230);
    const Rgba8 plate = light ? rgba8(255, 255, 255, 200) : rgba8(26, 28, 34, 200);
    const int levels = static_cast<int>(at_t.levels.size()) - 1;
    for (std::size_t lvl = 0; lvl < at_t.levels.size(); ++lvl) {
        const ImU32 c_lvl = curve_designer::level_color(static_cast<int>(lvl), levels);
        std::vector<glm::vec2> pts;
        for (std::size_t i = 0; i < at_t.levels[lvl].size(); ++i) {
            const auto p = geom::DeBoorTriangle::cartesian(at_t.levels[lvl][i]);
            if (!p) continue;
            pts.push_back(px(*p));
            const int index = at_t.first_index + static_cast<int>(i) + static_cast<int>(lvl);
            const std::vector<double> args =
                geom::deboor_point_arguments(g.knots, g.degree, static_cast<int>(lvl), index, t);
            pic.disk(pts.back(), 3.5f * k, c_lvl);
            LabelRequest& r = pic.label(pts.back(), polar_text(args, t, "t"), text_col,
                                        10 + static_cast<int>(lvl));
            r.plate = plate;
            r.tooltip = polar_text(args, std::nan(""), nullptr) + " = " +
                        point_text(geom::DeBoorTriangle::cartesian(at_t.levels[lvl][i]));
        }
        pic.polyline(std::move(pts), c_lvl, 1.4f * k);
    }
    // The triangle of the sliders' arguments, and its apex f(a_1, ..., a_p).
    const Rgba8 polar_col = light ? rgba8(170, 30, 170) : rgba8(235, 90, 235);
    for (std::size_t lvl = 1; lvl < at_args.levels.size(); ++lvl) {
        std::vector<glm::vec2> pts;
        for (const geom::HPoint& h : at_args.levels[lvl])
            if (auto p = geom::DeBoorTriangle::cartesian(h)) pts.push_back(px(*p));
        pic.polyline(std::move(pts), polar_col, 1.0f * k);
    }
    if (auto apex = geom::DeBoorTriangle::cartesian(at_args.levels.back().front())) {
        const glm::vec2 a = px(*apex);
        pic.disk(a, 7 * k, 0, polar_col, 2.2f * k);
        report_point("blossom/apex", a.x, a.y);
    }
    draw_picture(pic);
}

void curve_view(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c) {
    BlossomState& bs = ctx.ui.blossom;
    const geom::Curve& g = c.curve;
    const int p = g.degree, n = g.count();
    const float k = ctx.ui.scale();
    double t = ctx.ui.curve.trace_param(g);
    const geom::Interval dom = geom::domain(g);
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.6f);
    if (ImGui::SliderScalar("t (the designer's)", ImGuiDataType_Double, &t, &dom.lo, &dom.hi,
                            "%.4f")) {
        ctx.ui.curve.trace_t = normalize_param(dom, t);
        t = ctx.ui.curve.trace_param(g);
    }
    const int span = geom::default_blossom_span(g.knots, p, n, t);
    keep_arguments(bs.args, bs.object, bs.span, obj.id, span, p, t);
    const ArgumentRange range = argument_range(g.knots, p, span);
    ImGui::Text("Piece %d: [%.4g, %.4g)", span, g.knots[static_cast<std::size_t>(span)],
                g.knots[static_cast<std::size_t>(span + 1)]);
    if (ImGui::IsItemHovered())
        wrapped_tooltip("Its control points are f at " + std::to_string(p) +
                        " consecutive knots; each step of de Boor's algorithm puts t in place of "
                        "one knot, so the last point is f(t, .., t), the curve point.");
    argument_sliders(bs.args, range, "a");
    // Shortcuts: the diagonal, and each control point's knots.
    if (ImGui::Button("f(t, .., t)")) bs.args.assign(static_cast<std::size_t>(p), t);
    report_item("blossom/diagonal");
    for (int i = span - p; i <= span; ++i) {
        const std::string label = "P" + std::to_string(i);
        same_line_if_fits(button_width(label.c_str()));
        if (ImGui::Button(label.c_str()))
            bs.args = geom::deboor_point_arguments(g.knots, p, 0, i, t);
        report_item("blossom/" + label);
    }

    std::vector<geom::HPoint> Pw(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) Pw[static_cast<std::size_t>(i)] = g.hpoint(i);
    const geom::DeBoorTriangle at_t = geom::deboor_curve(g, t);
    const geom::DeBoorTriangle at_args = geom::deboor_polar(g.knots, p, Pw, span, bs.args);
    const auto value = geom::DeBoorTriangle::cartesian(at_args.levels.back().front());
    std::string is;
    if (same_arguments(bs.args, std::vector<double>(static_cast<std::size_t>(p), t)))
        is = " = C(t), the curve point";
    double control_gap = -1; // |f(args) - P_i| when the arguments are P_i's knots
    for (int i = span - p; i <= span; ++i)
        if (same_arguments(bs.args, geom::deboor_point_arguments(g.knots, p, 0, i, t))) {
            is = " = P" + std::to_string(i) + ", a control point";
            if (value) control_gap = glm::length(*value - g.points[static_cast<std::size_t>(i)]);
        }
    report_fact("blossom/control_gap", control_gap);
    text_wrapped("%s = %s%s", polar_text(bs.args, t, nullptr).c_str(), point_text(value).c_str(),
                 is.c_str());
    if (value)
        if (auto on_curve = geom::curve_point(g, t))
            report_fact("blossom/diagonal_gap",
                        same_arguments(bs.args, std::vector<double>(bs.args.size(), t))
                            ? glm::length(*value - *on_curve)
                            : -1.0);

    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    curve_canvas(ctx, c, at_t, at_args, t,
                 {origin.x, origin.y, avail.x, std::max(avail.y, 120 * k)});
}

// A surface: the stages at the indicator as lines, then f(u-args; v-args).
void surface_view(AppContext& ctx, const doc::Object& obj, const geom::Surface& s) {
    BlossomState& bs = ctx.ui.blossom;
    const glm::dvec2 uv = indicator_params(ctx.doc, obj);
    const int p = s.degree_u, q = s.degree_v;
    const int span_u = geom::default_blossom_span(s.knots_u, p, s.n_u, uv.x);
    const int span_v = geom::default_blossom_span(s.knots_v, q, s.n_v, uv.y);
    keep_arguments(bs.args, bs.object, bs.span, obj.id, span_u, p, uv.x);
    keep_arguments(bs.v_args, bs.v_object, bs.v_span, obj.id, span_v, q, uv.y);
    text_wrapped("Piece (%d, %d) at the indicator (u, v) = (%.4g, %.4g).", span_u, span_v, uv.x,
                 uv.y);
    argument_sliders(bs.args, argument_range(s.knots_u, p, span_u), "u");
    argument_sliders(bs.v_args, argument_range(s.knots_v, q, span_v), "v");
    if (ImGui::Button("f(u, .., u; v, .., v)")) {
        bs.args.assign(static_cast<std::size_t>(p), uv.x);
        bs.v_args.assign(static_cast<std::size_t>(q), uv.y);
    }
    report_item("blossom/diagonal");
    const auto value = geom::surface_blossom(s, span_u, span_v, bs.args, bs.v_args);
    std::string is;
    if (same_arguments(bs.args, std::vector<double>(bs.args.size(), uv.x)) &&
        same_arguments(bs.v_args, std::vector<double>(bs.v_args.size(), uv.y)))
        is = " = S(u, v)";
    text_wrapped("%s = %s%s", surface_polar_text(bs.args, bs.v_args, uv, false).c_str(),
                 point_text(value).c_str(), is.c_str());

    // The stages, every point labelled: the u-stage's row j is f(..; V[j+1], ..., V[j+q]).
    const geom::DeBoorSurfaceTrace trace = geom::deboor_surface(s, uv.x, uv.y);
    ImGui::Separator();
    ImGui::BeginChild("##blossom_stages");
    char line[256];
    for (int j = trace.v_stage.first_index; j <= trace.v_stage.first_index + q; ++j) {
        const geom::DeBoorTriangle& tri = trace.u_stage[static_cast<std::size_t>(j)];
        const std::vector<double> v_args = geom::deboor_point_arguments(s.knots_v, q, 0, j, uv.y);
        for (std::size_t lvl = 0; lvl < tri.levels.size(); ++lvl)
            for (std::size_t i = 0; i < tri.levels[lvl].size(); ++i) {
                const int index = tri.first_index + static_cast<int>(i) + static_cast<int>(lvl);
                const std::string label = surface_polar_text(
                    geom::deboor_point_arguments(s.knots_u, p, static_cast<int>(lvl), index, uv.x),
                    v_args, uv, true);
                std::snprintf(
                    line, sizeof line, "%s  %s", label.c_str(),
                    point_text(geom::DeBoorTriangle::cartesian(tri.levels[lvl][i])).c_str());
                ImGui::TextUnformatted(line);
            }
    }
    ImGui::Separator();
    const std::vector<double> u_all(static_cast<std::size_t>(p), uv.x);
    for (std::size_t lvl = 0; lvl < trace.v_stage.levels.size(); ++lvl)
        for (std::size_t i = 0; i < trace.v_stage.levels[lvl].size(); ++i) {
            const int index =
                trace.v_stage.first_index + static_cast<int>(i) + static_cast<int>(lvl);
            const std::string label = surface_polar_text(
                u_all,
                geom::deboor_point_arguments(s.knots_v, q, static_cast<int>(lvl), index, uv.y), uv,
                true);
            std::snprintf(
                line, sizeof line, "%s  %s", label.c_str(),
                point_text(geom::DeBoorTriangle::cartesian(trace.v_stage.levels[lvl][i])).c_str());
            ImGui::TextUnformatted(line);
        }
    ImGui::EndChild();
}

} // namespace

void draw_blossom_panel(AppContext& ctx) {
    note_hovered_view(ctx, StageView::blossom);
    const doc::Object* sel = ctx.doc.selected();
    if (sel && sel->curve_object()) {
        curve_view(ctx, *sel, *sel->curve_object());
        return;
    }
    const doc::Object* obj = nullptr;
    if (const geom::Surface* s = current_surface(ctx.doc, &obj)) {
        surface_view(ctx, *obj, *s);
        return;
    }
    text_wrapped("Select a curve or a surface: every point of de Boor's construction is its "
                 "blossom (polar form) at some arguments.");
}

} // namespace isoparm::ui
