// A coordinate plane at the size of a four-view cell or of the stage: every visible object's
// control net and wire projected, the selected control point's disk to drag in the plane (one
// undo step a drag), a press on another point's dot selects it; on the stage and in the
// four-view layout the wheel zooms, a right-drag pans and F fits (stage_controls.hpp).
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <imgui.h>
#include <string>
#include <vector>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/placement.hpp"
#include "ui/panels/canvas_hint.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/plane_canvas.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/control_net.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/plane_wire.hpp"

namespace isoparm::ui {

namespace {

Rgba8 rgba(const doc::Rgba& c, float alpha = 1) {
    auto byte = [](float x) { return static_cast<unsigned>(std::clamp(x, 0.f, 1.f) * 255 + 0.5f); };
    return rgba8(byte(c.r), byte(c.g), byte(c.b), byte(c.a * alpha));
}

// The box of every visible object's control points in the plane's two coordinates.
bool plane_box(const doc::Document& d, int a, int b, glm::dvec2& lo, glm::dvec2& hi) {
    bool any = false;
    for (const doc::Object& o : d.objects) {
        if (!o.visible) continue;
        for (const glm::dvec3& p : doc::control_points_of(o.shape)) {
            const glm::dvec2 q(p[a], p[b]);
            lo = any ? glm::min(lo, q) : q;
            hi = any ? glm::max(hi, q) : q;
            any = true;
        }
    }
    return any;
}

struct Dot {
    std::uint64_t object;
    int i, j;
    glm::dvec3 position;
};

std::vector<Dot> dots_of(const doc::Document& d) {
    std::vector<Dot> out;
    for (const doc::Object& o : d.objects) {
        if (!o.visible || !doc::display_of(d.view, o.id).control_points) continue;
        const ControlNet net = control_net_of(o);
        for (std::size_t q = 0; q < net.points.size(); ++q)
            out.push_back({o.id, net.ids[q].first, net.ids[q].second, net.points[q]});
    }
    return out;
}

std::unique_ptr<doc::Command> move_command(const doc::Object& o, int i, int j,
                                           const glm::dvec3& p) {
    return move_point_command(o, i, j, p);
}

// How one plane view maps the document: its axes, its map to pixels and its sizes.
struct PlaneFrame {
    PlaneAxes ax;
    PlaneMap map;
    float k;
    bool light;
    float disk_r;

    glm::dvec2 px(const glm::dvec3& p) const { return plane_to_pixel(map, {p[ax.a], p[ax.b]}); }
    glm::vec2 fpx(const glm::dvec3& p) const { return glm::vec2(px(p)); }
};

// A press on a dot selects it and holds it; dragging moves it in the plane (one undo step).
void plane_drag(AppContext& ctx, const PlaneFrame& f, int drag_id, const glm::dvec2& mouse) {
    PlaneDrag& pd = ctx.ui.plane_drag;
    const bool left = ImGui::IsMouseDown(ImGuiMouseButton_Left);
    if (ImGui::IsItemActivated() && left) {
        // The dot under the pointer (the selected point first) is selected and held.
        const std::vector<Dot> dots = dots_of(ctx.doc);
        const doc::Selection& sel = ctx.doc.view.selection;
        std::optional<Dot> hit;
        double best = f.disk_r * 1.6;
        for (const Dot& d : dots) {
            const bool selected = d.object == sel.object && d.i == sel.i && d.j == sel.j;
            const double dist = glm::length(f.px(d.position) - mouse) - (selected ? f.disk_r : 0);
            if (dist <= best) {
                best = dist;
                hit = d;
            }
        }
        if (hit) {
            ctx.doc.view.selection = {hit->object, hit->i, hit->j};
            pd.plane = drag_id;
            pd.frozen = f.map;
            pd.grab = mouse - f.px(hit->position);
            ctx.seal();
        }
    }
    if (ImGui::IsItemActive() && pd.plane == drag_id && left) {
        const doc::Selection sel = ctx.doc.view.selection;
        if (const doc::Object* o = ctx.doc.find(sel.object)) {
            const ControlNet net = control_net_of(*o);
            const int q = net.find(sel.i, sel.j);
            if (q >= 0) {
                const glm::dvec3 old = net.points[static_cast<std::size_t>(q)];
                const glm::dvec2 ab = pixel_to_plane(pd.frozen, mouse - pd.grab);
                glm::dvec3 p = old;
                p[f.ax.a] = ab.x;
                p[f.ax.b] = ab.y;
                if (p != old) ctx.execute(move_command(*o, sel.i, sel.j, p));
            }
        }
    }
    if (pd.plane == drag_id && (!ImGui::IsItemActive() || !left)) {
        pd.plane = -1;
        ctx.seal();
    }
    if (pd.plane != drag_id && canvas_hint_due(ctx.ui))
        ImGui::SetTooltip("Drag a point to move it in %s; wheel: zoom, right-drag: pan, F: fit",
                          f.ax.name);
}

// Every visible object's wire and (where shown) control net.
void draw_plane_wires(Picture& pic, const doc::Document& d, const PlaneFrame& f) {
    const doc::Colors& col = d.colors;
    const doc::Selection& sel = d.view.selection;
    for (const doc::Object& obj : d.objects) {
        if (!obj.visible) continue;
        const bool chosen = obj.id == sel.object;
        const Rgba8 wire = rgba(chosen ? col.selected_surface : col.surface, chosen ? 1.f : 0.75f);
        for (const Polyline3& line : object_wire(obj, 40)) {
            std::vector<glm::vec2> pts;
            for (const glm::dvec3& p : line) pts.push_back(f.fpx(p));
            pic.polyline(std::move(pts), wire, (chosen ? 1.6f : 1.1f) * f.k);
        }
        if (!doc::display_of(d.view, obj.id).control_net) continue;
        const ControlNet net = control_net_of(obj);
        for (const std::vector<int>& l : net.lines) {
            std::vector<glm::vec2> pts;
            for (int q : l) pts.push_back(f.fpx(net.points[static_cast<std::size_t>(q)]));
            pic.polyline(std::move(pts), rgba(col.control_net, chosen ? 0.8f : 0.4f), 1 * f.k);
        }
    }
}

// The control points' dots, and the selected point's disk to drag (`hot` when held or hovered).
void draw_plane_dots(Picture& pic, const doc::Document& d, const PlaneFrame& f, bool hot,
                     const std::string& name) {
    const doc::Colors& col = d.colors;
    const doc::Selection& sel = d.view.selection;
    for (const Dot& dot : dots_of(d)) {
        const bool selected = dot.object == sel.object && dot.i == sel.i && dot.j == sel.j;
        if (selected) continue;
        const glm::vec2 c = f.fpx(dot.position);
        pic.disk(c, 3.5f * f.k, rgba(col.control_points, 0.9f),
                 f.light ? rgba8(0, 0, 0, 160) : rgba8(0, 0, 0, 0), 1);
        if (dot.object == sel.object && doc::display_of(d.view, dot.object).point_ids)
            pic.label(c, point_name('P', dot.i, dot.j, d.find(dot.object)),
                      f.light ? rgba8(40, 40, 40) : rgba8(220, 220, 220), 0);
    }
    const doc::Object* so = d.find(sel.object);
    if (!so || !so->visible || !sel.has_point() || !doc::display_of(d.view, so->id).control_points)
        return;
    const ControlNet net = control_net_of(*so);
    const int q = net.find(sel.i, sel.j);
    if (q < 0) return;
    const glm::vec2 c = f.fpx(net.points[static_cast<std::size_t>(q)]);
    const float r = f.disk_r;
    pic.disk(c, r, rgba(col.selected_point), hot ? rgba8(255, 255, 255) : rgba8(0, 0, 0),
             1.5f * f.k);
    pic.keep_clear.push_back({c.x - r, c.y - r, 2 * r, 2 * r});
    pic.label(c, point_name('P', sel.i, sel.j, so), f.light ? rgba8(0, 0, 0) : rgba8(255, 255, 255),
              10)
        .plate = f.light ? rgba8(255, 255, 255, 210) : rgba8(20, 22, 28, 200);
    report_point(name + "/disk", c.x, c.y);
}

// The axes' names and the view's name, inside the frame.
void draw_plane_names(Picture& pic, const Rect& canvas, const PlaneFrame& f, int plane) {
    const char letters[3] = {'x', 'y', 'z'};
    const Rgba8 text = f.light ? rgba8(0, 0, 0) : rgba8(230, 230, 230);
    const float pad_px = 4 * f.k;
    pic.fixed_label({canvas.x + canvas.w - pad_px, canvas.y + canvas.h - pad_px},
                    std::string(1, letters[f.ax.a]), text, LabelAlign::bottom_right);
    pic.fixed_label({canvas.x + pad_px, canvas.y + pad_px}, std::string(1, letters[f.ax.b]), text,
                    LabelAlign::top_left);
    static const char* const titles[3] = {"xy (top)", "xz (front)", "yz (side)"};
    pic.fixed_label({canvas.x + canvas.w / 2, canvas.y + pad_px}, titles[plane],
                    f.light ? rgba8(90, 90, 90) : rgba8(150, 150, 160), LabelAlign::top_center, 90);
}

} // namespace

void draw_plane_view(AppContext& ctx, int plane, const Rect& canvas) {
    const PlaneAxes ax = plane_axes[plane];
    const float k = ctx.ui.scale();
    const bool light = ctx.ui.presentation;
    const std::string name = std::string("plane/") + ax.name;
    const PlaneDrag& pd = ctx.ui.plane_drag;
    const int drag_id = 10 + plane; // the Control point panel's canvases use 0..2

    ImGui::SetCursorScreenPos(ImVec2(canvas.x, canvas.y));
    ImGui::PushID(name.c_str());
    ImGui::InvisibleButton("##plane_view",
                           ImVec2(std::max(canvas.w, 1.f), std::max(canvas.h, 1.f)));
    ImGui::PopID();
    report_item(name);
    const CanvasView cv = canvas_view(ctx, name, canvas);
    glm::dvec2 lo(-1), hi(1);
    plane_box(ctx.doc, ax.a, ax.b, lo, hi);
    const double span = std::max(hi.x - lo.x, hi.y - lo.y);
    const glm::dvec2 pad(std::max(span * 0.15, 0.5));
    const PlaneMap fitted = fit_plane(canvas, lo - pad, hi + pad, 10 * k);
    const PlaneFrame f{ax, pd.plane == drag_id ? pd.frozen : view_map(cv, fitted), k, light, 7 * k};
    report_fact(name + "/units_per_px", f.map.units_per_px);

    const ImVec2 m = ImGui::GetIO().MousePos;
    plane_drag(ctx, f, drag_id, glm::dvec2(m.x, m.y));

    // The drawing, of the document as it is now.
    Picture pic = plane_picture(name, canvas, light, k);
    pic.style.offset = 7 * k;
    plane_origin_axes(pic, f.map, canvas, light, 1 * k);
    draw_plane_wires(pic, ctx.doc, f);
    draw_plane_dots(pic, ctx.doc, f, pd.plane == drag_id || ImGui::IsItemHovered(), name);
    draw_plane_names(pic, canvas, f, plane);
    draw_picture(pic);
}

} // namespace isoparm::ui
