// The 3D view's mouse (view3d_mouse.hpp): zoom, orbit and pan; picking, dragging and
// box-selecting control points; the selection's handle.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <imgui.h>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/doc/placement.hpp"
#include "core/geom/deboor.hpp"
#include "core/geom/status.hpp"
#include "ui/actions.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/view3d_mouse.hpp"
#include "ui/render/renderer.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/analysis.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/contrast.hpp"
#include "ui/view/control_net.hpp"
#include "ui/view/deboor_overlay.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/kinds/kind_view.hpp"
#include "ui/view/picking.hpp"
#include "ui/view/scene_builder.hpp"

namespace isoparm::ui {

namespace {

constexpr double pick_radius = 10.0; // pixels (scaled)

// Every control point the user can click: those of visible objects, when points are shown.
std::vector<PickedPoint> pick_candidates(const doc::Document& d) {
    std::vector<PickedPoint> out;
    for (const doc::Object& o : d.objects) {
        if (!o.visible || !doc::display_of(d.view, o.id).control_points) continue;
        // Its control net's points (control_net_of answers by kind; none for an implicit).
        const ControlNet net = control_net_of(o);
        for (std::size_t q = 0; q < net.points.size(); ++q)
            out.push_back({{o.id, net.ids[q].first, net.ids[q].second}, net.points[q]});
    }
    return out;
}

} // namespace

std::optional<PickedPoint> pick_point(const AppContext& ctx, const Viewport& vp,
                                      const glm::dvec2& mouse) {
    const std::vector<PickedPoint> cands = pick_candidates(ctx.doc);
    const glm::dmat4 m = view_projection(ctx.ui.camera, vp.aspect());
    std::vector<Projected> proj;
    proj.reserve(cands.size());
    for (const PickedPoint& c : cands) proj.push_back(project(m, vp, c.position));
    const auto k = pick_nearest(proj, mouse, pick_radius * ctx.ui.scale());
    if (!k) return std::nullopt;
    return cands[*k];
}

namespace {

int held_axis_key() {
    if (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_X))) return 0;
    if (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_Y))) return 1;
    if (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_Z))) return 2;
    return -1;
}

} // namespace

// The selection's handle where it is drawn: shown while two or more points are selected.
std::optional<HandleLayout> selection_handle(const AppContext& ctx, const Viewport& vp) {
    const SelectionState& st = ctx.ui.modeler.selection;
    if (!st.handle || st.points.size() < 2 || !ctx.doc.find(st.points.object)) return std::nullopt;
    if (!ctx.doc.view.display.control_points) return std::nullopt;
    HandleLayout h =
        handle_layout_3d(ctx.ui.camera, vp, selection_pivot(ctx), 70.0 * ctx.ui.scale());
    h.centre_radius = 8.0 * ctx.ui.scale();
    h.box_half = 5.0 * ctx.ui.scale();
    return h;
}

namespace {

// Starts a drag of the handle: the selected points and their positions at the press.
void start_handle_drag(AppContext& ctx, const Viewport& vp, HandlePart part,
                       const glm::dvec2& mouse, const HandleLayout& h) {
    SelectionState& st = ctx.ui.modeler.selection;
    const doc::Object* o = ctx.doc.find(st.points.object);
    if (!o || !may_edit_points(ctx, o->id)) return;
    SelectionGesture& g = st.gesture;
    g = {};
    g.kind = SelectionGesture::Kind::handle;
    g.part = part;
    g.press = g.now = mouse;
    g.points = st.points.points;
    for (const PointIndex& p : g.points) g.start.push_back(doc::position_of(o->shape, p));
    g.pivot = selection_pivot(ctx);
    g.pivot_px = h.centre;
    if (const int axis = handle_axis(part); axis >= 0) {
        glm::dvec3 e(0);
        e[axis] = 1;
        g.toward_viewer = glm::dot(e, camera_eye(ctx.ui.camera) - g.pivot) > 0;
    }
    (void)vp;
    ctx.seal(); // a new gesture: a new undo step
}

// The handle held: the map from the press to now, applied to the points as they were.
void drag_handle(AppContext& ctx, const Viewport& vp, const glm::dvec2& mouse) {
    SelectionState& st = ctx.ui.modeler.selection;
    SelectionGesture& g = st.gesture;
    g.now = mouse;
    const Camera& cam = ctx.ui.camera;
    // The pointer as if it had been pressed on the pivot itself (no jump at the first motion).
    const glm::dvec2 at = mouse + (g.pivot_px - g.press);
    const bool snap = snapping_now(ctx);
    glm::dmat4 m(1.0);
    const int axis = handle_axis(g.part);
    switch (g.part) {
    case HandlePart::centre:
    case HandlePart::arrow_x:
    case HandlePart::arrow_y:
    case HandlePart::arrow_z: {
        glm::dvec3 to = g.part == HandlePart::centre ? drag_in_view_plane(cam, vp, g.pivot, at)
                                                     : drag_along_axis(cam, vp, g.pivot, axis, at);
        if (snap) { // the pivot lands on the grid (along the arrow's axis only)
            const GridStep step = working_grid_step(ctx.ui);
            for (int a = 0; a < 3; ++a)
                if (g.part == HandlePart::centre || a == axis) to[a] = snap_to_grid(to[a], step);
        }
        m = doc::translation(to - g.pivot);
        break;
    }
    case HandlePart::ring_x:
    case HandlePart::ring_y:
    case HandlePart::ring_z:
        m = ring_turn(axis, g.pivot, g.pivot_px, g.press, mouse, g.toward_viewer,
                      snap ? 15.0 : 0.0);
        break;
    case HandlePart::scale:
        m = box_scale(g.pivot, g.pivot_px, g.press, mouse, snap ? 0.05 : 0.0);
        break;
    case HandlePart::none:
        return;
    }
    std::vector<glm::dvec3> to;
    for (const glm::dvec3& p : g.start) to.push_back(doc::apply_affine(m, p));
    const char* what = axis >= 0 && g.part >= HandlePart::ring_x && g.part <= HandlePart::ring_z
                           ? "Turn "
                       : g.part == HandlePart::scale ? "Scale "
                                                     : "Move ";
    ctx.execute(move_points_command(ctx, st.points.object, g.points, to,
                                    what + std::to_string(g.points.size()) + " points"));
}

// The points of the object whose screen positions are inside the box.
std::vector<PointIndex> points_in_box(const AppContext& ctx, const Viewport& vp,
                                      const doc::Object& o, const glm::dvec2& a,
                                      const glm::dvec2& b) {
    const glm::dmat4 m = view_projection(ctx.ui.camera, vp.aspect());
    const std::vector<PointIndex> all = doc::all_points(o.shape);
    std::vector<glm::dvec2> px;
    std::vector<PointIndex> visible;
    for (const PointIndex& p : all) {
        const Projected q = project(m, vp, doc::position_of(o.shape, p));
        if (!q.visible) continue;
        px.push_back(q.pixel);
        visible.push_back(p);
    }
    std::vector<PointIndex> out;
    for (std::size_t k : inside_box(px, a, b)) out.push_back(visible[k]);
    return out;
}

// The object a box selects in: the selected one, else the current surface.
const doc::Object* box_object(const AppContext& ctx) {
    if (const doc::Object* sel = ctx.doc.selected();
        sel && !doc::control_points_of(sel->shape).empty())
        return sel;
    const doc::Object* cur = nullptr;
    current_surface(ctx.doc, &cur);
    return cur;
}

// A dragged point snapped: to another point of its object on screen, or each coordinate the
// drag moves to the grid (the working plane's step) or an axis.
glm::dvec3 snapped_point(const AppContext& ctx, const Viewport& vp, const PointRef& ref,
                         const glm::dvec3& p, int axis) {
    if (!snapping_now(ctx)) return p;
    const doc::Object* o = ctx.doc.find(ref.object);
    if (!o) return p;
    const glm::dmat4 m = view_projection(ctx.ui.camera, vp.aspect());
    std::vector<glm::dvec3> others;
    std::vector<glm::dvec2> others_px;
    for (const PointIndex& q : doc::all_points(o->shape)) {
        if (q.i == ref.i && (q.j == ref.j || !two_index_points(o->shape))) continue;
        const glm::dvec3 x = doc::position_of(o->shape, q);
        const Projected pr = project(m, vp, x);
        if (!pr.visible) continue;
        others.push_back(x);
        others_px.push_back(pr.pixel);
    }
    bool free_axes[3] = {axis < 0, axis < 0, axis < 0};
    if (axis >= 0) free_axes[axis] = true;
    SnapSettings s = ctx.ui.modeler.snap.settings;
    s.radius_px *= ctx.ui.scale();
    const double h = std::max(1.0, vp.h);
    const double upp = 2 * ctx.ui.camera.distance * std::tan(ctx.ui.camera.fov_y / 2) / h;
    return snap_space_point(p, project(m, vp, p).pixel, s, working_grid_step(ctx.ui), upp,
                            free_axes, others, others_px)
        .p;
}

// A press in the view: on the selection's handle, on a control point (one of many selected
// keeps them), Ctrl on empty space starts a box, else the camera orbits or (Shift, right or
// middle button) pans.
void start_gesture(AppContext& ctx, const Viewport& vp, const glm::dvec2& mouse) {
    ImGuiIO& io = ImGui::GetIO();
    UiState& ui = ctx.ui;
    ViewDrag& drag = ui.drag;
    SelectionState& st = ui.modeler.selection;
    SelectionGesture& gesture = st.gesture;
    drag = {};
    drag.start_mouse = mouse;
    gesture = {};
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        const std::optional<HandleLayout> handle = selection_handle(ctx, vp);
        const HandlePart part =
            handle ? hit_handle(*handle, mouse, 7.0 * ui.scale()) : HandlePart::none;
        if (part != HandlePart::none && !io.KeyCtrl) {
            start_handle_drag(ctx, vp, part, mouse, *handle);
        } else if (const auto hit = !io.KeyCtrl ? pick_point(ctx, vp, mouse) : std::nullopt) {
            const PointIndex p{hit->ref.i, hit->ref.j};
            // A press on one of many selected points keeps the selection: a drag moves them
            // all (the handle's centre), a click without moving selects that one alone.
            const bool in_selection = st.points.size() > 1 && st.points.object == hit->ref.object &&
                                      st.points.contains(p) && !io.KeyShift;
            if (in_selection) {
                HandleLayout h = handle ? *handle : HandleLayout{};
                h.centre =
                    project(view_projection(ui.camera, vp.aspect()), vp, selection_pivot(ctx))
                        .pixel;
                start_handle_drag(ctx, vp, HandlePart::centre, mouse, h);
                gesture.points = st.points.points; // the press point itself moves with the pointer
            } else {
                if (!io.KeyShift) {
                    ctx.doc.view.selection = {hit->ref.object, hit->ref.i, hit->ref.j};
                    sync_selection(st.points, ctx.doc);
                    st.points.set(hit->ref.object, {p});
                }
                drag.kind = ViewDrag::Kind::point;
                drag.point = hit->ref;
                drag.start = hit->position;
                ctx.seal(); // a new gesture: a new undo step
            }
        } else if (io.KeyCtrl) {
            // Ctrl+drag on empty space: a box selects the points inside (Shift adds).
            gesture.kind = SelectionGesture::Kind::box;
            gesture.press = gesture.now = mouse;
            gesture.add = io.KeyShift;
        } else {
            drag.kind = io.KeyShift ? ViewDrag::Kind::pan : ViewDrag::Kind::orbit;
        }
    } else {
        drag.kind = ViewDrag::Kind::pan;
    }
}

// A held control point follows the pointer (along an axis when one is held or locked), snapped.
void drag_point(AppContext& ctx, const Viewport& vp, const glm::dvec2& mouse) {
    ImGuiIO& io = ImGui::GetIO();
    UiState& ui = ctx.ui;
    ViewDrag& drag = ui.drag;
    if (!drag.moved) return;
    // A constructed object's own point: ask first (the drag waits for the answer).
    if (!may_edit_points(ctx, drag.point.object)) {
        drag = {};
        return;
    }
    // Axis: X/Y/Z held picks it; Shift locks the axis the drag started along.
    int axis = held_axis_key();
    if (axis < 0 && io.KeyShift) {
        if (drag.axis < 0)
            drag.axis = dominant_axis(ui.camera, vp, drag.start, mouse - drag.start_mouse);
        axis = drag.axis;
    } else if (axis >= 0) {
        drag.axis = axis;
    } else {
        drag.axis = -1;
    }
    const glm::dvec3 p = axis >= 0 ? drag_along_axis(ui.camera, vp, drag.start, axis, mouse)
                                   : drag_in_view_plane(ui.camera, vp, drag.start, mouse);
    const glm::dvec3 q = snapped_point(ctx, vp, drag.point, p, axis);
    ctx.execute(point_move_command(ctx, drag.point.object, drag.point.i, drag.point.j, q));
}

// The release: a box selects, a click picks, toggles or clears; the gesture is one undo step.
void end_gesture(AppContext& ctx, const Viewport& vp, const glm::dvec2& mouse) {
    ImGuiIO& io = ImGui::GetIO();
    UiState& ui = ctx.ui;
    ViewDrag& drag = ui.drag;
    SelectionState& st = ui.modeler.selection;
    SelectionGesture& gesture = st.gesture;
    if (gesture.kind == SelectionGesture::Kind::box) {
        if (const doc::Object* o = box_object(ctx))
            select_points(ctx, o->id, points_in_box(ctx, vp, *o, gesture.press, gesture.now),
                          gesture.add);
    } else if (gesture.kind == SelectionGesture::Kind::handle &&
               glm::length(mouse - gesture.press) <= 2.0 && gesture.part == HandlePart::centre) {
        // A click on one of the selected points (not a drag): that point alone.
        if (const auto hit = pick_point(ctx, vp, mouse)) {
            ctx.doc.view.selection = {hit->ref.object, hit->ref.i, hit->ref.j};
            st.points.set(hit->ref.object, {{hit->ref.i, hit->ref.j}});
        }
    }
    if (drag.kind == ViewDrag::Kind::point && !drag.moved && io.KeyShift) {
        // Shift+click: the point in or out of the selection.
        toggle_point(ctx, drag.point.object, {drag.point.i, drag.point.j});
    }
    if (drag.kind == ViewDrag::Kind::orbit && !drag.moved) {
        ctx.doc.view.selection.i = ctx.doc.view.selection.j = -1; // a click on empty space
    }
    drag = {};
    gesture = {};
    ctx.seal();
}

} // namespace

void handle_mouse(AppContext& ctx, const Viewport& vp) {
    ImGuiIO& io = ImGui::GetIO();
    UiState& ui = ctx.ui;
    ViewDrag& drag = ui.drag;
    SelectionState& st = ui.modeler.selection;
    SelectionGesture& gesture = st.gesture;
    const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);

    if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f)
        zoom(ui.camera, std::pow(0.88, io.MouseWheel));

    if (ImGui::IsItemActivated()) start_gesture(ctx, vp, mouse);

    if (ImGui::IsItemActive() && gesture.kind != SelectionGesture::Kind::none) {
        if (gesture.kind == SelectionGesture::Kind::box)
            gesture.now = mouse;
        else if (glm::length(mouse - gesture.press) > 2.0)
            drag_handle(ctx, vp, mouse);
    }

    if (ImGui::IsItemActive() && drag.kind != ViewDrag::Kind::none) {
        const glm::dvec2 delta(io.MouseDelta.x, io.MouseDelta.y);
        if (glm::length(mouse - drag.start_mouse) > 2.0) drag.moved = true;
        switch (drag.kind) {
        case ViewDrag::Kind::orbit:
            orbit(ui.camera, delta.x, delta.y);
            break;
        case ViewDrag::Kind::pan:
            pan(ui.camera, delta.x, delta.y, vp.h);
            break;
        case ViewDrag::Kind::point:
            drag_point(ctx, vp, mouse);
            break;
        case ViewDrag::Kind::none:
            break;
        }
    }

    if (ImGui::IsItemDeactivated()) end_gesture(ctx, vp, mouse);
}

} // namespace isoparm::ui
