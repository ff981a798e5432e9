// The curve designer's plane canvas: control polygon, curve, knot points and de Boor's
// construction; clicks add, insert and select points, drags move them (one undo step each).
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

#include "core/doc/commands_curve.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/status.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/plane_canvas.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/polygon_hits.hpp"

namespace isoparm::ui::curve_designer {

namespace {

// The framing of the canvas: the control points' box in the plane with room around it (a
// single point or a flat polygon still gets some room). The box is kept while every point
// stays inside it and the curve and plane stay the same, so adding or moving a point does not
// shift the picture under the mouse; it grows when a point leaves it.
PlaneMap frame(CurveDesignerState& cd, std::uint64_t id, int plane, const geom::Curve& c,
               const Rect& canvas, int a, int b, float margin) {
    glm::dvec2 lo(c.points[0][a], c.points[0][b]), hi = lo;
    for (const glm::dvec3& p : c.points) {
        lo = glm::min(lo, glm::dvec2(p[a], p[b]));
        hi = glm::max(hi, glm::dvec2(p[a], p[b]));
    }
    const bool same = cd.frame_object == id && cd.frame_plane == plane;
    if (!same) {
        cd.view_zoom = 1;
        cd.view_pan = {0, 0};
    }
    cd.frame_object = id;
    cd.frame_plane = plane;
    PlaneMap m = kept_frame(cd.frame_lo, cd.frame_hi, same, lo, hi, 0.2, canvas, margin);
    // The canvas's own zoom and pan on top of the framing.
    m.units_per_px /= cd.view_zoom;
    m.center += cd.view_pan;
    return m;
}

// The other points of the curve in the canvas's plane: what a dragged point snaps to.
std::vector<glm::dvec2> other_points(const geom::Curve& g, const PlaneAxes& ax, int skip) {
    std::vector<glm::dvec2> out;
    for (int q = 0; q < g.count(); ++q)
        if (q != skip)
            out.push_back({g.points[static_cast<std::size_t>(q)][ax.a],
                           g.points[static_cast<std::size_t>(q)][ax.b]});
    return out;
}

const doc::CurveObject* curve_in(const AppContext& ctx, std::uint64_t id) {
    const doc::Object* o = ctx.doc.find(id);
    return o ? o->curve_object() : nullptr;
}

// Starts a drag of point i whose centre is under the mouse (a point just placed).
void start_drag(CurveDesignerState& cd, int i, const PlaneMap& map, const glm::dvec2& grab) {
    cd.drag_point = i;
    cd.frozen = map;
    cd.grab = grab;
}

// Presses on the canvas: select and drag a point, Ctrl+click a leg to insert, else append.
void handle_press(AppContext& ctx, std::uint64_t id, const geom::Curve& g, const PlaneAxes& ax,
                  const PlaneMap& map, const glm::dvec2& mouse) {
    CurveDesignerState& cd = ctx.ui.curve;
    const float k = ctx.ui.scale();
    const int normal = 3 - ax.a - ax.b;
    std::vector<glm::dvec2> px;
    for (const glm::dvec3& p : g.points) px.push_back(plane_to_pixel(map, {p[ax.a], p[ax.b]}));
    ctx.seal();
    cd.message.clear();
    cd.press = mouse;
    const double radius = 8 * k;
    // A curve built from a surface (an isocurve) follows it: ask before editing its points.
    if (!may_edit_points(ctx, id)) return;
    if (const std::optional<int> i = point_under(px, mouse, radius)) {
        ctx.doc.view.selection = {id, *i, -1};
        start_drag(cd, *i, map, mouse - px[static_cast<std::size_t>(*i)]);
        return;
    }
    const glm::dvec2 ab =
        snap_in_plane(ctx, map, pixel_to_plane(map, mouse), other_points(g, ax, -1));
    if (ImGui::GetIO().KeyCtrl) {
        const std::optional<LegHit> hit = leg_under(px, mouse, radius);
        if (!hit) {
            cd.message = "Ctrl+click on a leg of the control polygon to insert a point there.";
            return;
        }
        const int leg = hit->leg;
        // The normal coordinate follows the leg, so a planar curve stays in its plane.
        glm::dvec3 p = glm::mix(g.points[static_cast<std::size_t>(leg)],
                                g.points[static_cast<std::size_t>(leg + 1)], hit->s);
        p[ax.a] = ab.x;
        p[ax.b] = ab.y;
        if (ctx.execute(doc::insert_curve_point(id, leg + 1, p)))
            start_drag(cd, leg + 1, map, {0, 0});
        else
            cd.message = ctx.ui.status;
        return;
    }
    glm::dvec3 p(0);
    p[normal] = g.points.back()[normal]; // a plane curve stays in its plane
    p[ax.a] = ab.x;
    p[ax.b] = ab.y;
    const int n = g.count();
    if (ctx.execute(doc::insert_curve_point(id, n, p)))
        start_drag(cd, n, map, {0, 0});
    else
        cd.message = ctx.ui.status;
}

} // namespace

ImU32 rgba(const doc::Rgba& c, float alpha) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, c.a * alpha));
}

ImU32 level_color(int level, int levels) {
    if (level >= levels) return IM_COL32(235, 40, 40, 255);
    // From cyan (first level) through green to yellow: far from the red final point.
    const float t = levels > 1 ? static_cast<float>(level - 1) / static_cast<float>(levels - 1) : 0;
    float r, g, b;
    ImGui::ColorConvertHSVtoRGB(0.5f - 0.36f * t, 0.75f, 0.95f, r, g, b);
    return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, 1));
}

void fit_curve_canvas(CurveDesignerState& cd) {
    cd.view_zoom = 1;
    cd.view_pan = {0, 0};
    cd.frame_object = 0; // framed afresh at the next frame
}

int canvas_plane(const AppContext& ctx, const doc::CurveObject& c) {
    switch (c.plane) {
    case doc::CurvePlane::xy:
        return 0;
    case doc::CurvePlane::xz:
        return 1;
    case doc::CurvePlane::yz:
        return 2;
    case doc::CurvePlane::free3d:
        break;
    }
    return std::clamp(ctx.ui.curve.view_plane, 0, 2);
}

namespace {

// Zoom about the pointer (wheel), pan (right or middle drag); the panel's Fit frames again.
void zoom_and_pan(CurveDesignerState& cd, const PlaneMap& map, const glm::dvec2& mouse) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.MouseWheel != 0) {
        const glm::dvec2 before = pixel_to_plane(map, mouse);
        cd.view_zoom = std::clamp(cd.view_zoom * std::pow(1.15, io.MouseWheel), 0.05, 200.0);
        PlaneMap zoomed = map;
        zoomed.units_per_px = map.units_per_px * std::pow(1.15, -io.MouseWheel);
        cd.view_pan += before - pixel_to_plane(zoomed, mouse);
    }
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0) ||
        ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0))
        cd.view_pan += glm::dvec2(-io.MouseDelta.x, io.MouseDelta.y) * map.units_per_px;
}

// The held point follows the pointer in the plane, snapped (a refusal is the panel's message).
void drag_held_point(AppContext& ctx, std::uint64_t id, const PlaneAxes& ax,
                     const glm::dvec2& mouse) {
    CurveDesignerState& cd = ctx.ui.curve;
    const doc::CurveObject* cur = curve_in(ctx, id);
    if (cur && cd.drag_point < cur->curve.count()) {
        const glm::dvec3 old = cur->curve.points[static_cast<std::size_t>(cd.drag_point)];
        const glm::dvec2 ab =
            snap_in_plane(ctx, cd.frozen, pixel_to_plane(cd.frozen, mouse - cd.grab),
                          other_points(cur->curve, ax, cd.drag_point));
        glm::dvec3 p = old;
        p[ax.a] = ab.x;
        p[ax.b] = ab.y;
        if (p != old && !ctx.execute(point_move_command(ctx, id, cd.drag_point, -1, p)))
            cd.message = ctx.ui.status;
    }
}

using CanvasPixel = std::function<glm::vec2(const glm::dvec3&)>;

// The control polygon, the curve (uniform samples plus the knots, so corners at multiple knots
// stay sharp) and its knot points.
void draw_curve_and_polygon(const AppContext& ctx, Picture& pic, const geom::Curve& g,
                            const CanvasPixel& gx) {
    const float k = ctx.ui.scale();
    const doc::Colors& col = ctx.doc.colors;
    // The control polygon.
    std::vector<glm::vec2> line;
    for (const glm::dvec3& p : g.points) line.push_back(gx(p));
    pic.polyline(line, rgba(col.control_net, 0.7f), 1.2f * k);
    // The curve: uniform samples plus the knots, so corners at multiple knots stay sharp.
    const geom::Interval d = geom::domain(g);
    std::vector<double> ts = geom::uniform_params(d.lo, d.hi, 401);
    for (int i = g.degree + 1; i < g.count(); ++i)
        ts.push_back(g.knots[static_cast<std::size_t>(i)]);
    std::sort(ts.begin(), ts.end());
    line.clear();
    auto flush = [&] {
        pic.polyline(line, rgba(col.selected_surface), 2.2f * k);
        line.clear();
    };
    for (double t : ts) {
        if (const auto p = geom::curve_point(g, t))
            line.push_back(gx(*p));
        else
            flush(); // a zero weight sum: the curve does not exist there
    }
    flush();
    // Knot points C(u_k): where the polynomial pieces join.
    for (const geom::KnotRun& run : geom::knot_runs(g.knots)) {
        if (run.value < d.lo || run.value > d.hi) continue;
        if (const auto p = geom::curve_point(g, run.value)) {
            const glm::vec2 q = gx(*p);
            const float r = (2.5f + static_cast<float>(run.multiplicity > 1)) * k;
            pic.box({q.x - r, q.y - r}, {q.x + r, q.y + r}, rgba(col.knot_curves));
        }
    }
}

// The control points, labelled P0..Pn while the labels stay readable; the selected one larger
// (white-ringed while held or hovered).
void draw_curve_points(const AppContext& ctx, Picture& top, const doc::CurveObject& cur,
                       std::uint64_t id, const CanvasPixel& gx, bool hot) {
    const float k = ctx.ui.scale();
    const doc::Colors& col = ctx.doc.colors;
    const geom::Curve& g = cur.curve;
    const int sel = ctx.doc.view.selection.object == id ? ctx.doc.view.selection.i : -1;
    const Rgba8 text_col = ImGui::GetColorU32(ImGuiCol_Text);
    // A closed curve repeats its first p points at its end: one label says both names.
    const bool closed = cur.knot_mode == doc::CurveKnotMode::closed;
    const int own = closed ? g.count() - g.degree : g.count();
    auto name = [&](int i) {
        const int first = closed ? i % own : i;
        std::string s = "P" + std::to_string(first);
        if (closed && first < g.degree) s += "=P" + std::to_string(first + own);
        return s;
    };
    for (int i = 0; i < g.count(); ++i) {
        const glm::vec2 q = gx(g.points[static_cast<std::size_t>(i)]);
        report_point("curve/point/" + std::to_string(i), q.x, q.y);
        if (i == sel || (closed && i >= own && sel == i - own)) continue;
        top.disk(q, 4 * k, rgba(col.control_points));
        if (g.count() <= 40 && i < own) top.label(q, name(i), text_col, 5);
    }
    if (sel >= 0 && sel < g.count()) {
        const glm::vec2 q = gx(g.points[static_cast<std::size_t>(sel)]);
        top.disk(q, 6.5f * k, rgba(col.selected_point), hot ? rgba8(255, 255, 255) : rgba8(0, 0, 0),
                 1.5f * k);
        top.keep_clear.push_back({q.x - 6.5f * k, q.y - 6.5f * k, 13 * k, 13 * k});
        top.label(q, name(sel), text_col, 30);
    }
}

// De Boor's construction at the trace parameter, on top: every level's polygon.
void draw_curve_deboor(const AppContext& ctx, Picture& top, const geom::Curve& g,
                       const CanvasPixel& gx) {
    const float k = ctx.ui.scale();
    const double t = ctx.ui.curve.trace_param(g);
    const geom::DeBoorTriangle tri = geom::deboor_curve(g, t);
    const int levels = static_cast<int>(tri.levels.size()) - 1;
    for (int lv = 1; lv <= levels; ++lv) {
        std::vector<glm::vec2> pts;
        for (const geom::HPoint& h : tri.levels[static_cast<std::size_t>(lv)])
            if (const auto p = geom::DeBoorTriangle::cartesian(h)) pts.push_back(gx(*p));
        const ImU32 lc = level_color(lv, levels);
        top.polyline(pts, lc, 1.6f * k);
        for (const glm::vec2& q : pts) top.disk(q, (lv == levels ? 5.f : 3.f) * k, lc);
    }
    if (const auto p = geom::DeBoorTriangle::cartesian(tri.levels.back().front()))
        top.label(gx(*p), "C(" + geom::format_short(t, 3) + ")", rgba8(235, 60, 60), 40).tooltip =
            "C(" + geom::format_number(t) + ")";
}

} // namespace

void plane_canvas(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c,
                  const Rect& canvas) {
    CurveDesignerState& cd = ctx.ui.curve;
    const std::uint64_t id = obj.id;
    const int plane = canvas_plane(ctx, c);
    const PlaneAxes ax = plane_axes[plane];
    const float k = ctx.ui.scale();
    ImGui::SetCursorScreenPos(ImVec2(canvas.x, canvas.y));
    ImGui::InvisibleButton("##curve_canvas", ImVec2(canvas.w, canvas.h),
                           ImGuiButtonFlags_MouseButtonLeft);
    report_item("curve/canvas");
    // On the stage the wheel zooms and a right-drag pans (the kept framing, seen through it).
    const CanvasView cv = canvas_view(ctx, "curve", canvas);
    const PlaneMap map =
        cd.drag_point >= 0
            ? cd.frozen
            : view_map(cv, frame(cd, id, plane, c.curve, canvas, ax.a, ax.b, 14 * k));
    const ImVec2 m = ImGui::GetIO().MousePos;
    const glm::dvec2 mouse(m.x, m.y);
    if (ImGui::IsItemHovered() && cd.drag_point < 0) zoom_and_pan(cd, map, mouse);
    if (ImGui::IsItemActivated() && ImGui::IsMouseDown(ImGuiMouseButton_Left))
        handle_press(ctx, id, c.curve, ax, map, mouse);
    // A press that has not moved yet moves nothing (rounding would nudge the point).
    if (ImGui::IsItemActive() && cd.drag_point >= 0 && mouse != cd.press)
        drag_held_point(ctx, id, ax, mouse);
    if (ImGui::IsItemDeactivated() && cd.drag_point >= 0) {
        cd.drag_point = -1;
        ctx.seal();
    }
    const bool hovered = ImGui::IsItemHovered();

    // Draw what the document holds now (the gesture may have changed it).
    const doc::CurveObject* cur = curve_in(ctx, id);
    if (!cur) return;
    const geom::Curve& g = cur->curve;
    auto gx = [&](const glm::dvec3& p) {
        return glm::vec2(plane_to_pixel(map, {p[ax.a], p[ax.b]}));
    };

    const bool light = ctx.ui.presentation;
    Picture pic = plane_picture("curve", canvas, light, k);
    pic.style.offset = 5 * k;
    if (ctx.ui.modeler.snap.grid_shown)
        plane_grid(pic, map, canvas, light, plane_grid_step(ctx.ui, map));
    plane_origin_axes(pic, map, canvas, light);

    draw_curve_and_polygon(ctx, pic, g, gx);
    draw_curve_analysis(ctx, g, ctx.ui.curve.trace_param(g), pic, gx);
    // Over them: the points, de Boor's construction; every text is placed with the others.
    Picture& top = pic;
    const Rgba8 text_col = ImGui::GetColorU32(ImGuiCol_Text);
    draw_curve_points(ctx, top, *cur, id, gx, cd.drag_point >= 0 || hovered);
    if (cd.trace) draw_curve_deboor(ctx, top, g, gx);
    const char names[3] = {'x', 'y', 'z'};
    const float in = 4 * k;
    top.fixed_label({canvas.x + canvas.w - in, canvas.y + canvas.h - 2 * k},
                    std::string(1, names[ax.a]), text_col, LabelAlign::bottom_right);
    top.fixed_label({canvas.x + in, canvas.y + 2 * k}, std::string(1, names[ax.b]), text_col,
                    LabelAlign::top_left);
    top.fixed_label({canvas.x + canvas.w / 2, canvas.y + 2 * k}, std::string(ax.name) + " plane",
                    ImGui::GetColorU32(ImGuiCol_TextDisabled), LabelAlign::top_center, 90);
    draw_picture(top);
}

} // namespace isoparm::ui::curve_designer
