// The control-point panel: for the selected point, three planes (xy, xz, yz) where its
// disk is dragged, exact coordinates, and the weight of rational types.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <imgui.h>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/doc/commands.hpp"
#include "ui/animation_actions.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/plane_canvas.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/control_net.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/text_wrap.hpp"

namespace isoparm::ui {

namespace {

ImU32 u32(const doc::Rgba& c, float alpha = 1) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha));
}

StageView stage_plane_view(int plane) {
    return plane == 0   ? StageView::plane_xy
           : plane == 1 ? StageView::plane_xz
                        : StageView::plane_yz;
}

// The framing of one plane: the control points' box in that plane, with a margin.
PlaneMap frame_plane(const ControlNet& net, const Rect& canvas, int a, int b, float margin) {
    glm::dvec2 lo(net.points[0][a], net.points[0][b]), hi = lo;
    for (const glm::dvec3& p : net.points) {
        lo = glm::min(lo, glm::dvec2(p[a], p[b]));
        hi = glm::max(hi, glm::dvec2(p[a], p[b]));
    }
    // A flat direction (a planar grid seen edge-on) still gets some room to move into.
    const double span = std::max(hi.x - lo.x, hi.y - lo.y);
    const glm::dvec2 pad(std::max(span * 0.15, 0.5));
    return fit_plane(canvas, lo - pad, hi + pad, margin);
}

// The selection's handle in a plane: shown while two or more points are selected.
std::optional<HandleLayout> plane_handle(const AppContext& ctx, const doc::Object& obj,
                                         const PlaneMap& map, const PlaneAxes& ax) {
    const SelectionState& st = ctx.ui.modeler.selection;
    if (!st.handle || st.points.size() < 2 || st.points.object != obj.id) return std::nullopt;
    const float k = ctx.ui.scale();
    // At most 0.4 of the plane's shorter side: on a projector's small planes (75 px in
    // presentation mode at 1024x768) a full-size arrow's tip lay outside the plane, where
    // nobody can grab it.
    const double size =
        std::min(48.0 * k, 0.4 * static_cast<double>(std::min(map.canvas.w, map.canvas.h)));
    HandleLayout h = handle_layout_plane(map, ax.a, ax.b, selection_pivot(ctx), size);
    h.centre_radius = 6.0 * k;
    h.box_half = 4.5 * k;
    return h;
}

// The plane's handle held: the map from the press to now, on the points as they were.
void drag_plane_handle(AppContext& ctx, const PlaneMap& map, const PlaneAxes& ax,
                       const glm::dvec2& mouse) {
    SelectionState& st = ctx.ui.modeler.selection;
    SelectionGesture& g = st.gesture;
    g.now = mouse;
    const bool snap = snapping_now(ctx);
    const int normal = 3 - ax.a - ax.b;
    glm::dmat4 m(1.0);
    switch (g.part) {
    case HandlePart::centre:
    case HandlePart::arrow_x:
    case HandlePart::arrow_y:
    case HandlePart::arrow_z: {
        const glm::dvec2 d = pixel_to_plane(map, mouse) - pixel_to_plane(map, g.press);
        glm::dvec3 to = g.pivot;
        const int axis = handle_axis(g.part);
        if (g.part == HandlePart::centre || axis == ax.a) to[ax.a] += d.x;
        if (g.part == HandlePart::centre || axis == ax.b) to[ax.b] += d.y;
        if (snap) {
            const GridStep step = plane_grid_step(ctx.ui, map);
            for (int a : {ax.a, ax.b})
                if (to[a] != g.pivot[a]) to[a] = snap_to_grid(to[a], step);
        }
        m = doc::translation(to - g.pivot);
        break;
    }
    case HandlePart::ring_x:
    case HandlePart::ring_y:
    case HandlePart::ring_z:
        // The plane's normal points at the viewer in xy (z) and yz (x), away in xz (y).
        m = ring_turn(normal, g.pivot, g.pivot_px, g.press, mouse, normal != 1, snap ? 15.0 : 0.0);
        break;
    case HandlePart::scale:
        m = box_scale(g.pivot, g.pivot_px, g.press, mouse, snap ? 0.05 : 0.0);
        break;
    case HandlePart::none:
        return;
    }
    std::vector<glm::dvec3> to;
    for (const glm::dvec3& p : g.start) to.push_back(doc::apply_affine(m, p));
    ctx.execute(move_points_command(ctx, st.points.object, g.points, to,
                                    "Move " + std::to_string(g.points.size()) + " points"));
}

// One control point plane as it is this frame: its axes, its map to pixels, the selected point
// and its disk, and the selection's handle.
struct CpPlane {
    const doc::Object& obj;
    const ControlNet& net;
    int plane;
    PlaneAxes ax;
    PlaneMap map;
    float k;
    int si, sj;
    glm::dvec3 sel;
    glm::dvec2 disk;
    float disk_r;
    std::optional<HandleLayout> handle;

    glm::dvec2 dot_px(std::size_t q) const {
        return plane_to_pixel(map, {net.points[q][ax.a], net.points[q][ax.b]});
    }
};

// A press: on the handle (many points), on the selected point's disk, on another dot, or on
// empty space (a box).
void cp_plane_press(AppContext& ctx, const CpPlane& c, const glm::dvec2& mouse) {
    const doc::Object& obj = c.obj;
    const ControlNet& net = c.net;
    const int plane = c.plane;
    const PlaneMap& map = c.map;
    const float k = c.k;
    const glm::dvec2& disk = c.disk;
    const float disk_r = c.disk_r;
    const std::optional<HandleLayout>& handle = c.handle;
    PlaneDrag& pd = ctx.ui.plane_drag;
    SelectionState& st = ctx.ui.modeler.selection;
    SelectionGesture& g = st.gesture;
    const ImGuiIO& io = ImGui::GetIO();
    auto dot_px = [&](std::size_t q) { return c.dot_px(q); };
    const HandlePart part = handle ? hit_handle(*handle, mouse, 6.0 * k) : HandlePart::none;
    std::optional<std::size_t> dot;
    for (std::size_t q = 0; q < net.points.size(); ++q)
        if (glm::length(dot_px(q) - mouse) <= 5 * k) dot = q;
    if (part != HandlePart::none && !io.KeyShift) {
        if (may_edit_points(ctx, obj.id)) {
            g = {};
            g.kind = SelectionGesture::Kind::handle;
            g.view = plane;
            g.part = part;
            g.press = g.now = mouse;
            g.points = st.points.points;
            for (const PointIndex& p : g.points) g.start.push_back(doc::position_of(obj.shape, p));
            g.pivot = selection_pivot(ctx);
            g.pivot_px = handle->centre;
            pd.frozen = map;
            ctx.seal();
        }
    } else if (glm::length(mouse - disk) <= disk_r * 1.6 && !io.KeyShift) {
        if (may_edit_points(ctx, obj.id)) {
            pd.plane = plane;
            pd.frozen = map;
            pd.grab = mouse - disk;
            ctx.seal();
        }
    } else if (dot) {
        const auto [i, j] = net.ids[*dot];
        if (io.KeyShift) {
            toggle_point(ctx, obj.id, {i, j});
        } else {
            ctx.doc.view.selection = {obj.id, i, j};
            st.points.set(obj.id, {{i, j}});
        }
    } else {
        // Empty space: a box selects the points inside it (Shift adds to the selection).
        g = {};
        g.kind = SelectionGesture::Kind::box;
        g.view = plane;
        g.press = g.now = mouse;
        g.add = io.KeyShift;
        pd.frozen = map;
    }
}

// While held: the box follows, the handle moves, turns or scales, the disk moves its point.
// Returns whether a point moved.
bool cp_plane_hold(AppContext& ctx, const CpPlane& c, const glm::dvec2& mouse) {
    const doc::Object& obj = c.obj;
    const ControlNet& net = c.net;
    const int plane = c.plane;
    const PlaneAxes& ax = c.ax;
    const int si = c.si, sj = c.sj;
    const glm::dvec3& sel = c.sel;
    PlaneDrag& pd = ctx.ui.plane_drag;
    SelectionGesture& g = ctx.ui.modeler.selection.gesture;
    bool moved = false;
    if (ImGui::IsItemActive() && g.view == plane) {
        if (g.kind == SelectionGesture::Kind::box)
            g.now = mouse;
        else if (g.kind == SelectionGesture::Kind::handle && glm::length(mouse - g.press) > 1.0) {
            drag_plane_handle(ctx, pd.frozen, ax, mouse);
            moved = true;
        }
    }
    if (ImGui::IsItemActive() && pd.plane == plane) {
        glm::dvec2 ab = pixel_to_plane(pd.frozen, mouse - pd.grab);
        std::vector<glm::dvec2> others;
        for (std::size_t q = 0; q < net.points.size(); ++q)
            if (net.ids[q] != std::pair{si, sj})
                others.push_back({net.points[q][ax.a], net.points[q][ax.b]});
        ab = snap_in_plane(ctx, pd.frozen, ab, others);
        glm::dvec3 p = sel;
        p[ax.a] = ab.x;
        p[ax.b] = ab.y;
        if (p != sel) {
            ctx.execute(point_move_command(ctx, obj.id, si, sj, p));
            moved = true;
        }
    }
    return moved;
}

// The release: a box selects the points inside it; the gesture ends (one undo step).
void cp_plane_release(AppContext& ctx, const CpPlane& c) {
    const doc::Object& obj = c.obj;
    const ControlNet& net = c.net;
    const int plane = c.plane;
    PlaneDrag& pd = ctx.ui.plane_drag;
    SelectionGesture& g = ctx.ui.modeler.selection.gesture;
    auto dot_px = [&](std::size_t q) { return c.dot_px(q); };
    if (g.view == plane && g.kind == SelectionGesture::Kind::box) {
        std::vector<glm::dvec2> px;
        for (std::size_t q = 0; q < net.points.size(); ++q) px.push_back(dot_px(q));
        std::vector<PointIndex> inside;
        for (std::size_t q : inside_box(px, g.press, g.now))
            inside.push_back({net.ids[q].first, net.ids[q].second});
        select_points(ctx, obj.id, inside, g.add);
    }
    if (g.view == plane) g = {};
    if (pd.plane == plane) pd.plane = -1;
    ctx.seal();
}

// The selection's handle: the ring about the plane's normal, the two axes' arrows, the centre
// and the scale box.
void draw_cp_handle(Picture& pic, const HandleLayout& h, const PlaneAxes& ax, int plane, float k) {
    const HandleLayout* handle = &h;
    const Rgba8 colors[3] = {rgba8(240, 80, 80), rgba8(90, 215, 90), rgba8(90, 140, 255)};
    const int normal = 3 - ax.a - ax.b;
    std::vector<glm::vec2> ring;
    for (const glm::dvec2& p : handle->ring[normal]) ring.push_back(glm::vec2(p));
    pic.polyline(std::move(ring), (colors[normal] & 0x00FFFFFF) | 0xB0000000, 1.5f * k, true);
    for (int c : {ax.a, ax.b}) {
        pic.line(glm::vec2(handle->centre), glm::vec2(handle->tip[c]), colors[c], 2.5f * k);
        pic.disk(glm::vec2(handle->tip[c]), 4 * k, colors[c]);
        const char* axis_names[3] = {"x", "y", "z"};
        report_point("cp/handle" + std::to_string(plane) + "/" + axis_names[c],
                     static_cast<float>(handle->tip[c].x), static_cast<float>(handle->tip[c].y));
    }
    pic.disk(glm::vec2(handle->centre), static_cast<float>(handle->centre_radius),
             rgba8(255, 255, 255, 210), rgba8(0, 0, 0), 1.5f * k);
    const float hb = static_cast<float>(handle->box_half);
    const glm::vec2 sb(handle->scale_box);
    pic.box(sb - glm::vec2(hb), sb + glm::vec2(hb), rgba8(250, 210, 80, 230));
    report_point("cp/handle" + std::to_string(plane), static_cast<float>(handle->centre.x),
                 static_cast<float>(handle->centre.y));
    report_point("cp/handle" + std::to_string(plane) + "/scale", sb.x, sb.y);
}

// The selected point's disk is dragged (one undo step a drag), a press on another dot selects
// that point (Shift: adds it or takes it out), a drag on empty space draws a box that selects
// the points inside, and with many points selected their handle moves, turns and scales them.
// Returns whether it moved a point (the document changed).
bool plane_canvas(AppContext& ctx, const doc::Object& obj, const ControlNet& net, int plane,
                  const Rect& canvas) {
    const PlaneAxes ax = plane_axes[plane];
    const float k = ctx.ui.scale();
    PlaneDrag& pd = ctx.ui.plane_drag;
    SelectionState& st = ctx.ui.modeler.selection;
    SelectionGesture& g = st.gesture;
    const PlaneMap map =
        pd.plane == plane || (g.view == plane && g.kind != SelectionGesture::Kind::none)
            ? pd.frozen
            : frame_plane(net, canvas, ax.a, ax.b, 8 * k);
    const int si = ctx.doc.view.selection.i, sj = ctx.doc.view.selection.j;
    const glm::dvec3 sel = net.points[static_cast<std::size_t>(net.find(si, sj))];
    const glm::dvec2 disk = plane_to_pixel(map, {sel[ax.a], sel[ax.b]});
    const float disk_r = 7 * k;
    const std::optional<HandleLayout> handle = plane_handle(ctx, obj, map, ax);

    ImGui::SetCursorScreenPos(ImVec2(canvas.x, canvas.y));
    ImGui::PushID(plane);
    ImGui::InvisibleButton("##plane", ImVec2(canvas.w, canvas.h));
    report_item("cp/plane" + std::to_string(plane));
    report_point("cp/disk" + std::to_string(plane), static_cast<float>(disk.x),
                 static_cast<float>(disk.y));
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 m = io.MousePos;
    const glm::dvec2 mouse(m.x, m.y);
    const CpPlane c{obj, net, plane, ax, map, k, si, sj, sel, disk, disk_r, handle};
    if (ImGui::IsItemActivated()) cp_plane_press(ctx, c, mouse);
    const bool moved = ImGui::IsItemActive() && cp_plane_hold(ctx, c, mouse);
    if (ImGui::IsItemDeactivated()) cp_plane_release(ctx, c);
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();

    if (hovered) ctx.ui.stage.hovered_next = stage_plane_view(plane);
    const bool light = ctx.ui.presentation;
    Picture pic = plane_picture(std::string("cp/") + ax.name, canvas, light, k);
    if (ctx.ui.modeler.snap.grid_shown)
        plane_grid(pic, map, canvas, light, plane_grid_step(ctx.ui, map));
    plane_origin_axes(pic, map, canvas, light);
    // The net, projected.
    const doc::Colors& col = ctx.doc.colors;
    auto px = [&](int q) {
        const glm::dvec3& p = net.points[static_cast<std::size_t>(q)];
        return glm::vec2(plane_to_pixel(map, {p[ax.a], p[ax.b]}));
    };
    const Rgba8 net_col = u32(col.control_net, 0.45f);
    for (const std::vector<int>& l : net.lines) {
        std::vector<glm::vec2> line;
        for (int q : l) line.push_back(px(q));
        pic.polyline(std::move(line), net_col, 1 * k);
    }
    // Dots only while they stay readable; a dense net is clearer as lines alone. The selected
    // points are drawn in the selected point's colour (always).
    const bool many = st.points.size() > 1 && st.points.object == obj.id;
    const bool report_dots = ui_report_enabled() && net.points.size() <= 144;
    for (std::size_t q = 0; q < net.points.size(); ++q) {
        if (report_dots) {
            const glm::vec2 d = px(static_cast<int>(q));
            report_point("cp/dot" + std::to_string(plane) + "/" + std::to_string(net.ids[q].first) +
                             "," + std::to_string(net.ids[q].second),
                         d.x, d.y);
        }
        const bool chosen = many && st.points.contains({net.ids[q].first, net.ids[q].second});
        if (chosen)
            pic.disk(px(static_cast<int>(q)), 4.0f * k, u32(col.selected_point));
        else if (net.points.size() <= 144)
            pic.disk(px(static_cast<int>(q)), 2.5f * k, u32(col.control_points, 0.8f));
    }
    const bool active = pd.plane == plane;
    pic.disk(glm::vec2(disk), disk_r, u32(col.selected_point),
             active || hovered ? rgba8(255, 255, 255) : rgba8(0, 0, 0), 1.5f * k);
    pic.keep_clear.push_back({static_cast<float>(disk.x) - disk_r,
                              static_cast<float>(disk.y) - disk_r, 2 * disk_r, 2 * disk_r});
    if (g.view == plane && g.kind == SelectionGesture::Kind::box)
        pic.box(glm::min(glm::vec2(g.press), glm::vec2(g.now)),
                glm::max(glm::vec2(g.press), glm::vec2(g.now)), rgba8(120, 170, 255, 40),
                rgba8(140, 190, 255, 220), 1.5f * k);
    if (handle) draw_cp_handle(pic, *handle, ax, plane, k);
    // Axis names: horizontal bottom-right, vertical top-left, the plane's name on top.
    const char names[3] = {'x', 'y', 'z'};
    const Rgba8 tc = ImGui::GetColorU32(ImGuiCol_Text);
    const float in = 3 * k;
    pic.fixed_label({canvas.x + canvas.w - in, canvas.y + canvas.h - in},
                    std::string(1, names[ax.a]), tc, LabelAlign::bottom_right);
    pic.fixed_label({canvas.x + in, canvas.y + in}, std::string(1, names[ax.b]), tc,
                    LabelAlign::top_left);
    pic.fixed_label({canvas.x + canvas.w / 2, canvas.y + in}, ax.name,
                    ImGui::GetColorU32(ImGuiCol_TextDisabled), LabelAlign::top_center, 90);
    draw_picture(pic);
    return moved;
}

// The selected control point of a surface or a triangle, as the fields edit it.
struct SelectedPoint {
    glm::dvec3 position{0};
    double weight = 1;
    bool rational = false;
    const char* type = "";
};
// This panel edits surfaces' and triangles' points (editor_of); curves have the designer.
SelectedPoint selected_point(const doc::Object& obj, int i, int j) {
    return std::visit(doc::overloaded{
                          [&](const doc::SurfaceObject& so) -> SelectedPoint {
                              const geom::Surface& s = so.surface;
                              return {s.point(i, j), s.weight(i, j), geom::is_rational(s.type),
                                      geom::name_of(s.type)};
                          },
                          [](const doc::CurveObject&) { return SelectedPoint{}; },
                          [](const doc::ImplicitObject&) { return SelectedPoint{}; },
                          [&](const doc::TriangleObject& to) -> SelectedPoint {
                              const geom::TrianglePatch& t = to.patch;
                              const auto at = static_cast<std::size_t>(
                                  geom::TrianglePatch::index(t.degree, i, j));
                              return {t.points[at], t.weights[at], t.rational,
                                      t.rational ? "rational_triangle_bezier" : "triangle_bezier"};
                          },
                      },
                      obj.shape);
}

void coordinate_fields(AppContext& ctx, const doc::Object& obj) {
    const int i = ctx.doc.view.selection.i, j = ctx.doc.view.selection.j;
    glm::dvec3 p = selected_point(obj, i, j).position;
    const char* labels[3] = {"x", "y", "z"};
    const ImGuiStyle& st = ImGui::GetStyle();
    const float avail = ImGui::GetContentRegionAvail().x;
    const float label = ImGui::CalcTextSize("x").x + st.ItemInnerSpacing.x;
    // Three in a row while each shows a whole value, else one under the other.
    const float whole = ImGui::CalcTextSize("-00.0000").x + st.FramePadding.x * 2;
    const float in_row = (avail - st.ItemSpacing.x * 2) / 3 - label;
    const bool row = in_row >= whole;
    for (int a = 0; a < 3; ++a) {
        if (a > 0 && row) ImGui::SameLine();
        ImGui::SetNextItemWidth(row ? in_row : std::max(avail - label, whole));
        double value = p[a];
        // One value per widget: each field is one edit (and one undo step).
        const bool edited = ImGui::InputDouble(labels[a], &value, 0, 0, "%.4f");
        report_item(std::string("cp/") + labels[a]);
        if (edited && std::isfinite(value) && value != p[a] && may_edit_points(ctx, obj.id)) {
            p[a] = value;
            ctx.execute(point_move_command(ctx, obj.id, i, j, p));
        }
        if (ImGui::IsItemDeactivatedAfterEdit()) ctx.seal();
    }
}

// What a weight does to the surface, under the weight's fields.
const char* weight_note(double w) {
    // With every weight >= 0 the rational basis functions are still >= 0 and sum to 1
    // wherever the surface exists, so it stays in the hull of the points with w > 0
    // (Piegl & Tiller sec. 4.4); only a negative weight breaks that.
    if (w == 0)
        return "w = 0: this point no longer pulls on the surface. The convex-hull property "
               "still holds while no weight is negative: only negative weights break it.";
    if (w < 0)
        return "w < 0: the convex-hull property no longer holds; the surface is pushed away "
               "and may leave the hull of the control net.";
    return "Larger w pulls the surface toward the point, smaller pushes it away.";
}

void weight_controls(AppContext& ctx, const doc::Object& obj) {
    const int i = ctx.doc.view.selection.i, j = ctx.doc.view.selection.j;
    const SelectedPoint sp = selected_point(obj, i, j);
    if (!sp.rational && obj.triangle()) {
        text_wrapped("Weight: this triangular patch is non-rational (all weights 1).");
        // Unit weights keep the shape: the patch only becomes one whose weights can change.
        if (ImGui::Button("Make it rational")) {
            geom::TrianglePatch t = *obj.triangle();
            t.rational = true;
            ctx.seal();
            ctx.execute(doc::edit_shape(obj.id, doc::TriangleObject{std::move(t)},
                                        "Make " + obj.name + " rational"));
            ctx.seal();
        }
        return;
    }
    if (!sp.rational) {
        text_wrapped("Weight: this %s surface is non-rational (all weights 1). Weights "
                     "belong to rational Bezier and NURBS surfaces.",
                     sp.type);
        return;
    }
    double w = sp.weight;
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(point_name('w', i, j, &obj).c_str());
    ImGui::SameLine();
    const ImGuiStyle& st = ImGui::GetStyle();
    const float field =
        std::max(90 * ctx.ui.scale(), ImGui::CalcTextSize("-0.0000").x + st.FramePadding.x * 2);
    // The slider and the typed field side by side while both show their values whole.
    const float slider_w = ImGui::GetContentRegionAvail().x - field - st.ItemSpacing.x;
    const bool side_by_side = slider_w >= ImGui::CalcTextSize("-0.000").x * 1.5f;
    ImGui::SetNextItemWidth(side_by_side ? slider_w : ImGui::GetContentRegionAvail().x);
    const double lo = -2.0, hi = 6.0;
    double slider = w;
    if (ImGui::SliderScalar("##weight", ImGuiDataType_Double, &slider, &lo, &hi, "%.3f") &&
        slider != w && may_edit_points(ctx, obj.id))
        ctx.execute(doc::set_weight(obj.id, i, j, slider));
    if (ImGui::IsItemDeactivated()) ctx.seal();
    if (side_by_side) ImGui::SameLine();
    ImGui::SetNextItemWidth(field);
    double typed = w;
    // Any finite value may be typed, beyond the slider's range, zero and negative included.
    if (ImGui::InputDouble("##weight_typed", &typed, 0, 0, "%.4g") && std::isfinite(typed) &&
        typed != w && may_edit_points(ctx, obj.id))
        ctx.execute(doc::set_weight(obj.id, i, j, typed));
    report_item("cp/weight");
    if (ImGui::IsItemDeactivatedAfterEdit()) ctx.seal();
    // The weight on the Animate slider: watch the surface as w runs from 0 to 5 (not an edit).
    if (ImGui::SmallButton("Animate this weight")) {
        AnimationState& anim = ctx.ui.modeler.animation;
        anim.form_kind = static_cast<int>(doc::AnimatedKind::weight);
        anim.form_from = 0;
        anim.form_to = 5;
        start_animation(ctx, weight_target_of_selection(ctx.doc), anim.form_seconds,
                        static_cast<doc::Repeat>(anim.form_repeat), true);
    }
    report_item("cp/animate_weight");

    const double now = selected_point(*ctx.doc.find(obj.id), i, j).weight;
    const ImVec4 warn = ctx.ui.presentation ? ImVec4(0.7f, 0.25f, 0, 1) : ImVec4(1, 0.72f, 0.3f, 1);
    ImGui::PushStyleColor(ImGuiCol_Text,
                          now > 0 ? ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled) : warn);
    text_wrapped("%s", weight_note(now));
    ImGui::PopStyleColor();
}

// Many selected points: their number and centroid, the pivot, typed moves, turns, scales and
// mirrors (each one undo step), and symmetric editing.
void selection_section(AppContext& ctx) {
    SelectionState& st = ctx.ui.modeler.selection;
    const float k = ctx.ui.scale();
    const std::string summary = points_selection_summary(ctx);
    const bool many = !summary.empty();
    if (!ImGui::CollapsingHeader(many ? ("Selection: " + summary + "###selection").c_str()
                                      : "Selection###selection"))
        return;
    report_item("cp/selection");
    if (!many) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("Shift+click points to add them, drag a box on empty space (Ctrl+drag "
                           "in the 3D view), R: the point's row, Shift+R: its column, Ctrl+A: "
                           "all. Many points move, turn and scale by their handle or below.");
        ImGui::PopStyleColor();
    }
    int pivot = st.pivot == PivotChoice::centroid ? 0 : 1;
    ImGui::TextUnformatted("About");
    ImGui::SameLine();
    if (ImGui::RadioButton("centroid", &pivot, 0)) st.pivot = PivotChoice::centroid;
    ImGui::SameLine();
    if (ImGui::RadioButton("point", &pivot, 1)) {
        st.pivot = PivotChoice::point;
        st.chosen_pivot = selection_pivot(ctx);
    }
    if (st.pivot == PivotChoice::point) {
        ImGui::SetNextItemWidth(std::min(ImGui::GetContentRegionAvail().x, 240 * k));
        ImGui::InputScalarN("pivot", ImGuiDataType_Double, &st.chosen_pivot[0], 3, nullptr, nullptr,
                            "%.4g");
    }
    const float w3 = std::min(ImGui::GetContentRegionAvail().x * 0.6f, 220 * k);
    ImGui::SetNextItemWidth(w3);
    ImGui::InputScalarN("##move", ImGuiDataType_Double, st.move, 3, nullptr, nullptr, "%.4g");
    report_item("cp/sel/move");
    ImGui::SameLine();
    if (ImGui::Button("Move by") && many)
        transform_selection(ctx, doc::translation({st.move[0], st.move[1], st.move[2]}),
                            "Move " + std::to_string(st.points.size()) + " points");
    report_item("cp/sel/move_apply");
    ImGui::SetNextItemWidth(70 * k);
    ImGui::InputDouble("degrees about", &st.turn_degrees, 0, 0, "%.4g");
    ImGui::SameLine();
    const char* axes[] = {"x", "y", "z"};
    ImGui::SetNextItemWidth(45 * k);
    ImGui::Combo("##turnaxis", &st.turn_axis, axes, 3);
    ImGui::SameLine();
    if (ImGui::Button("Turn") && many && std::isfinite(st.turn_degrees))
        transform_selection(ctx, doc::rotation(st.turn_axis, st.turn_degrees),
                            "Turn " + std::to_string(st.points.size()) + " points");
    ImGui::SetNextItemWidth(w3);
    ImGui::InputScalarN("##scale", ImGuiDataType_Double, st.scale, 3, nullptr, nullptr, "%.4g");
    report_item("cp/sel/scale");
    ImGui::SameLine();
    if (ImGui::Button("Scale by") && many)
        transform_selection(ctx, doc::scaling({st.scale[0], st.scale[1], st.scale[2]}),
                            "Scale " + std::to_string(st.points.size()) + " points");
    report_item("cp/sel/scale_apply");
    const char* planes[] = {"x", "y", "z"};
    ImGui::TextUnformatted("Mirror in");
    for (int a = 0; a < 3; ++a) {
        ImGui::SameLine();
        const std::string label = std::string(planes[a]) + " = pivot's##mirror" + planes[a];
        if (ImGui::SmallButton(label.c_str()) && many)
            transform_selection(ctx, doc::mirror(a),
                                std::string("Mirror ") + std::to_string(st.points.size()) +
                                    " points in " + planes[a]);
    }
    const char* sym[] = {"off", "x = 0", "y = 0", "z = 0"};
    int symmetry = st.symmetry + 1;
    ImGui::SetNextItemWidth(90 * k);
    if (ImGui::Combo("symmetric editing (a point's mirror partner follows)", &symmetry, sym, 4))
        st.symmetry = symmetry - 1;
    report_item("cp/symmetry");
    ImGui::Checkbox("handle", &st.handle);
}

// The three planes of the selected point, in a row when the panel is wide, else wrapped, with
// room left under them for the fields and the weight. False when no point is selected after
// them (a canvas's command may change the document).
bool plane_canvases(AppContext& ctx) {
    const float k = ctx.ui.scale();
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    ImVec2 avail = ImGui::GetContentRegionAvail();
    // The width as if the scrollbar were shown: ImGui shows it a frame after the content
    // outgrew the panel, and planes sized to the width without it made the content taller,
    // then narrower with it, then shorter again, every other frame (the planes flickered by
    // 6 px at 1920x1080 and a click could miss a button that moved 13 px).
    if (ImGui::GetScrollMaxY() <= 0) avail.x -= ImGui::GetStyle().ScrollbarSize;
    // Room below for the coordinates, the weight's two fields and its note, so the note (the
    // convex-hull warning) is never below the fold on a projector.
    double w = 1;
    if (const doc::Object* o = ctx.doc.selected(); o && has_valid_point(ctx.doc))
        w = selected_point(*o, ctx.doc.view.selection.i, ctx.doc.view.selection.j).weight;
    const float note_h = ImGui::CalcTextSize(weight_note(w), nullptr, false, avail.x).y;
    const ImGuiStyle& st = ImGui::GetStyle();
    const float whole = ImGui::CalcTextSize("-00.0000").x + st.FramePadding.x * 2;
    const float in_row =
        (avail.x - st.ItemSpacing.x * 2) / 3 - ImGui::CalcTextSize("x").x - st.ItemInnerSpacing.x;
    const int field_rows = (in_row >= whole ? 1 : 3) + 2; // x y z, then the weight's two fields
    const float below = ImGui::GetFrameHeightWithSpacing() * static_cast<float>(field_rows) +
                        note_h + st.ItemSpacing.y * 2;
    // The arrangement (3 in a row, 2 + 1, or a column) that gives the largest planes.
    int cols = 3;
    float side = 0;
    for (int c = 1; c <= 3; ++c) {
        const int r = (3 + c - 1) / c;
        const float s =
            std::min((avail.x - spacing * static_cast<float>(c - 1)) / static_cast<float>(c),
                     (avail.y - below) / static_cast<float>(r) - spacing);
        if (s > side) {
            side = s;
            cols = c;
        }
    }
    // Planes of at least the least size a person can aim in, but never wider than the column
    // allows in their row: in presentation mode at 1024x768 three of the least size in a row
    // were cut at the panel's edge (and more rows would push the fields below the fold).
    const float row_fits =
        (avail.x - spacing * static_cast<float>(cols - 1)) / static_cast<float>(cols);
    // A pixel at least: a headless picture can give the column no width at all (ImGui asserts
    // on a button of no size).
    side = std::max({side, std::min(60 * k, row_fits), 1.0f});
    const int rows = (3 + cols - 1) / cols;
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const doc::Object* obj = ctx.doc.selected();
    ControlNet net = obj ? control_net_of(*obj) : ControlNet{};
    for (int p = 0; p < 3; ++p) {
        const int r = p / cols, c = p % cols;
        const Rect canvas{origin.x + static_cast<float>(c) * (side + spacing),
                          origin.y + static_cast<float>(r) * (side + spacing), side, side};
        // The net again only after a canvas moved a point (obj may not outlive the command).
        if (!obj || !has_valid_point(ctx.doc)) break;
        if (net.find(ctx.doc.view.selection.i, ctx.doc.view.selection.j) < 0) continue;
        if (plane_canvas(ctx, *obj, net, p, canvas)) {
            obj = ctx.doc.selected();
            net = obj ? control_net_of(*obj) : ControlNet{};
        }
    }
    ImGui::SetCursorScreenPos(
        ImVec2(origin.x, origin.y + static_cast<float>(rows) * (side + spacing)));
    return ctx.doc.selected() && has_valid_point(ctx.doc);
}

// The panel's first line: the point and its object, its type faint, the stage button at the
// right end; cut to the column with the whole in the tooltip (a triangle's type is long).
void header(AppContext& ctx, const std::string& what, const std::string& type) {
    const float room = ImGui::GetContentRegionAvail().x - ImGui::GetFrameHeight() -
                       ImGui::GetStyle().ItemSpacing.x * 2;
    const MeasureText measure = imgui_measure();
    const std::string first = shortened(what, room, measure);
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(first.c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s %s", what.c_str(), type.c_str());
    const float left = room - measure(first).x - ImGui::GetStyle().ItemSpacing.x;
    const std::string second = shortened(type, left, measure);
    if (left > measure("(..)").x) {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", second.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s %s", what.c_str(), type.c_str());
    }
    stage_button(ctx, StageView::plane_xy);
}

} // namespace

// A triangle's point: the planes with its triangular net, its fields and its weight.
void triangle_point_panel(AppContext& ctx, const doc::Object& obj) {
    const int i = ctx.doc.view.selection.i, j = ctx.doc.view.selection.j;
    header(ctx, point_name('P', i, j, &obj) + " of " + obj.name,
           "(" + std::string(selected_point(obj, i, j).type) + ", degree " +
               std::to_string(obj.triangle()->degree) + ")");
    const std::uint64_t id = obj.id; // obj may not outlive a canvas's command
    if (!plane_canvases(ctx)) return;
    const doc::Object* now = ctx.doc.find(id);
    if (!now || !now->triangle()) return;
    coordinate_fields(ctx, *now);
    now = ctx.doc.find(id);
    if (now && has_valid_point(ctx.doc)) weight_controls(ctx, *now);
}

void draw_control_point_panel(AppContext& ctx) {
    note_hovered_view(ctx, StageView::plane_xy);
    const doc::Object* obj = ctx.doc.selected();
    if (obj && obj->triangle() && has_valid_point(ctx.doc)) {
        triangle_point_panel(ctx, *obj);
        return;
    }
    const geom::Surface* s = obj ? obj->surface() : nullptr;
    if (!s || !has_valid_point(ctx.doc)) {
        const doc::Object* shown = obj;
        if (!shown || !shown->surface()) current_surface(ctx.doc, &shown);
        if (shown && !doc::display_of(ctx.doc.view, shown->id).control_points)
            text_wrapped("The control points of %s are hidden: C (or Display > Control points) "
                         "shows them to click one in the 3D view.",
                         shown->name.c_str());
        else if (shown && !shown->visible)
            text_wrapped("%s is hidden: its box in the Objects tab shows it again.",
                         shown->name.c_str());
        else
            text_wrapped("Click a control point in the 3D view to select it; it can then "
                         "be moved here in the xy, xz and yz planes.");
        if (const geom::Surface* cur = current_surface(ctx.doc, &obj); cur && obj) {
            ImGui::Spacing();
            ImGui::TextDisabled("Or choose one of %s:", obj->name.c_str());
            int ij[2] = {0, 0};
            ImGui::SetNextItemWidth(120 * ctx.ui.scale());
            if (ImGui::InputInt2("i, j", ij, ImGuiInputTextFlags_EnterReturnsTrue) && ij[0] >= 0 &&
                ij[0] < cur->n_u && ij[1] >= 0 && ij[1] < cur->n_v)
                ctx.doc.view.selection = {obj->id, ij[0], ij[1]};
        }
        return;
    }
    const int i = ctx.doc.view.selection.i, j = ctx.doc.view.selection.j;
    header(ctx, point_name('P', i, j, s->n_u, s->n_v) + " of " + obj->name,
           "(" + std::string(geom::name_of(s->type)) + ")");
    if (!plane_canvases(ctx)) return;
    obj = ctx.doc.selected();
    if (!obj || !obj->surface() || !has_valid_point(ctx.doc)) return;
    coordinate_fields(ctx, *obj);
    obj = ctx.doc.selected();
    if (!obj || !obj->surface() || !has_valid_point(ctx.doc)) return;
    weight_controls(ctx, *obj);
    if (!ctx.doc.selected() || !has_valid_point(ctx.doc)) return;
    selection_section(ctx);
}

} // namespace isoparm::ui
