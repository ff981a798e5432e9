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
#include <vector>

#include "core/doc/commands.hpp"
#include "ui/animation_actions.hpp"
#include "ui/modeler_actions.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/plane_canvas.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/control_net.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

ImVec2 iv(const glm::dvec2& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

ImU32 u32(const doc::Rgba& c, float alpha = 1) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha));
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
    HandleLayout h = handle_layout_plane(map, ax.a, ax.b, selection_pivot(ctx), 48.0 * k);
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
    bool moved = false;
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
    auto dot_px = [&](std::size_t q) {
        return plane_to_pixel(map, {net.points[q][ax.a], net.points[q][ax.b]});
    };
    if (ImGui::IsItemActivated()) {
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
                for (const PointIndex& p : g.points)
                    g.start.push_back(doc::position_of(obj.shape, p));
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
    if (ImGui::IsItemDeactivated()) {
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
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();

    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 a(canvas.x, canvas.y), b(canvas.x + canvas.w, canvas.y + canvas.h);
    const bool light = ctx.ui.presentation;
    const GridStep step = plane_grid_step(ctx.ui, map);
    begin_plane_canvas(dl, map, canvas, light, ctx.ui.modeler.snap.grid_shown ? &step : nullptr);
    // The net, projected.
    const doc::Colors& col = ctx.doc.colors;
    auto px = [&](int q) {
        const glm::dvec3& p = net.points[static_cast<std::size_t>(q)];
        return iv(plane_to_pixel(map, {p[ax.a], p[ax.b]}));
    };
    // The net's lines as polylines (far fewer vertices than one line per segment).
    std::vector<ImVec2> line;
    const ImU32 net_col = u32(col.control_net, 0.45f);
    for (const std::vector<int>& l : net.lines) {
        line.clear();
        for (int q : l) line.push_back(px(q));
        dl->AddPolyline(line.data(), static_cast<int>(line.size()), net_col, 0, 1 * k);
    }
    // Dots only while they stay readable; a dense net is clearer as lines alone. The selected
    // points are drawn in the selected point's colour (always).
    const bool many = st.points.size() > 1 && st.points.object == obj.id;
    const bool report_dots = ui_report_enabled() && net.points.size() <= 144;
    for (std::size_t q = 0; q < net.points.size(); ++q) {
        if (report_dots) {
            const ImVec2 d = px(static_cast<int>(q));
            report_point("cp/dot" + std::to_string(plane) + "/" + std::to_string(net.ids[q].first) +
                             "," + std::to_string(net.ids[q].second),
                         d.x, d.y);
        }
        const bool chosen = many && st.points.contains({net.ids[q].first, net.ids[q].second});
        if (chosen)
            dl->AddCircleFilled(px(static_cast<int>(q)), 4.0f * k, u32(col.selected_point), 12);
        else if (net.points.size() <= 144)
            dl->AddCircleFilled(px(static_cast<int>(q)), 2.5f * k, u32(col.control_points, 0.8f),
                                8);
    }
    const bool active = pd.plane == plane;
    dl->AddCircleFilled(iv(disk), disk_r, u32(col.selected_point), 20);
    dl->AddCircle(iv(disk), disk_r,
                  active || hovered ? IM_COL32(255, 255, 255, 255) : IM_COL32(0, 0, 0, 255), 20,
                  1.5f * k);
    if (g.view == plane && g.kind == SelectionGesture::Kind::box) {
        dl->AddRectFilled(iv(g.press), iv(g.now), IM_COL32(120, 170, 255, 40));
        dl->AddRect(iv(g.press), iv(g.now), IM_COL32(140, 190, 255, 220), 0, 0, 1.5f * k);
    }
    if (handle) {
        const ImU32 colors[3] = {IM_COL32(240, 80, 80, 255), IM_COL32(90, 215, 90, 255),
                                 IM_COL32(90, 140, 255, 255)};
        const int normal = 3 - ax.a - ax.b;
        std::vector<ImVec2> ring;
        for (const glm::dvec2& p : handle->ring[normal]) ring.push_back(iv(p));
        dl->AddPolyline(ring.data(), static_cast<int>(ring.size()),
                        (colors[normal] & 0x00FFFFFF) | 0xB0000000, ImDrawFlags_Closed, 1.5f * k);
        for (int c : {ax.a, ax.b}) {
            dl->AddLine(iv(handle->centre), iv(handle->tip[c]), colors[c], 2.5f * k);
            dl->AddCircleFilled(iv(handle->tip[c]), 4 * k, colors[c], 12);
            const char* names[3] = {"x", "y", "z"};
            report_point("cp/handle" + std::to_string(plane) + "/" + names[c],
                         static_cast<float>(handle->tip[c].x),
                         static_cast<float>(handle->tip[c].y));
        }
        dl->AddCircleFilled(iv(handle->centre), static_cast<float>(handle->centre_radius),
                            IM_COL32(255, 255, 255, 210), 16);
        dl->AddCircle(iv(handle->centre), static_cast<float>(handle->centre_radius),
                      IM_COL32(0, 0, 0, 255), 16, 1.5f * k);
        const float hb = static_cast<float>(handle->box_half);
        const ImVec2 sb = iv(handle->scale_box);
        dl->AddRectFilled(ImVec2(sb.x - hb, sb.y - hb), ImVec2(sb.x + hb, sb.y + hb),
                          IM_COL32(250, 210, 80, 230));
        report_point("cp/handle" + std::to_string(plane), static_cast<float>(handle->centre.x),
                     static_cast<float>(handle->centre.y));
        report_point("cp/handle" + std::to_string(plane) + "/scale", sb.x, sb.y);
    }
    dl->PopClipRect();
    dl->AddRect(a, b, light ? IM_COL32(0, 0, 0, 255) : IM_COL32(110, 115, 130, 255), 0, 0, 1 * k);
    // Axis names: horizontal bottom-right, vertical top-left.
    const char names[3] = {'x', 'y', 'z'};
    const char h[2] = {names[ax.a], 0}, v[2] = {names[ax.b], 0};
    const ImU32 tc = ImGui::GetColorU32(ImGuiCol_Text);
    dl->AddText(
        ImVec2(b.x - ImGui::CalcTextSize(h).x - 4 * k, b.y - ImGui::GetTextLineHeight() - 2 * k),
        tc, h);
    dl->AddText(ImVec2(a.x + 4 * k, a.y + 2 * k), tc, v);
    dl->AddText(ImVec2(a.x + (canvas.w - ImGui::CalcTextSize(ax.name).x) / 2, a.y + 2 * k),
                ImGui::GetColorU32(ImGuiCol_TextDisabled), ax.name);
    return moved;
}

// The selected control point of a surface or a triangle, as the fields edit it.
struct SelectedPoint {
    glm::dvec3 position{0};
    double weight = 1;
    bool rational = false;
    const char* type = "";
};
SelectedPoint selected_point(const doc::Object& obj, int i, int j) {
    if (const geom::TrianglePatch* t = obj.triangle()) {
        const auto at = static_cast<std::size_t>(geom::TrianglePatch::index(t->degree, i, j));
        return {t->points[at], t->weights[at], t->rational,
                t->rational ? "rational_triangle_bezier" : "triangle_bezier"};
    }
    const geom::Surface& s = *obj.surface();
    return {s.point(i, j), s.weight(i, j), geom::is_rational(s.type), geom::name_of(s.type)};
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

void weight_controls(AppContext& ctx, const doc::Object& obj) {
    const int i = ctx.doc.view.selection.i, j = ctx.doc.view.selection.j;
    const SelectedPoint sp = selected_point(obj, i, j);
    if (!sp.rational && obj.triangle()) {
        ImGui::TextWrapped("Weight: this triangular patch is non-rational (all weights 1).");
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
        ImGui::TextWrapped("Weight: this %s surface is non-rational (all weights 1). Weights "
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
    if (now == 0) {
        ImGui::PushStyleColor(ImGuiCol_Text, warn);
        // With every weight >= 0 the rational basis functions are still >= 0 and sum to 1
        // wherever the surface exists, so it stays in the hull of the points with w > 0
        // (Piegl & Tiller sec. 4.4); only a negative weight breaks that.
        ImGui::TextWrapped("w = 0: this point no longer pulls on the surface. The "
                           "convex-hull property still holds while no weight is negative: "
                           "only negative weights break it.");
        ImGui::PopStyleColor();
    } else if (now < 0) {
        ImGui::PushStyleColor(ImGuiCol_Text, warn);
        ImGui::TextWrapped("w < 0: the convex-hull property no longer holds; the surface "
                           "is pushed away and may leave the hull of the control net.");
        ImGui::PopStyleColor();
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        ImGui::TextWrapped("Larger w pulls the surface toward the point, smaller pushes it away.");
        ImGui::PopStyleColor();
    }
}

// Many selected points: their number and centroid, the pivot, typed moves, turns, scales and
// mirrors (each one undo step), and symmetric editing.
void selection_section(AppContext& ctx) {
    SelectionState& st = ctx.ui.modeler.selection;
    const float k = ctx.ui.scale();
    const std::string summary = selection_summary(ctx);
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
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float below =
        ImGui::GetFrameHeightWithSpacing() * 3 + ImGui::GetTextLineHeightWithSpacing() * 3;
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
    const int rows = (3 + cols - 1) / cols;
    side = std::max(side, 60 * k);
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

} // namespace

// A triangle's point: the planes with its triangular net, its fields and its weight.
void triangle_point_panel(AppContext& ctx, const doc::Object& obj) {
    const int i = ctx.doc.view.selection.i, j = ctx.doc.view.selection.j;
    ImGui::Text("%s of %s", point_name('P', i, j, &obj).c_str(), obj.name.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("(%s, degree %d)", selected_point(obj, i, j).type, obj.triangle()->degree);
    const std::uint64_t id = obj.id; // obj may not outlive a canvas's command
    if (!plane_canvases(ctx)) return;
    const doc::Object* now = ctx.doc.find(id);
    if (!now || !now->triangle()) return;
    coordinate_fields(ctx, *now);
    now = ctx.doc.find(id);
    if (now && has_valid_point(ctx.doc)) weight_controls(ctx, *now);
}

void draw_control_point_panel(AppContext& ctx) {
    const doc::Object* obj = ctx.doc.selected();
    if (obj && obj->triangle() && has_valid_point(ctx.doc)) {
        triangle_point_panel(ctx, *obj);
        return;
    }
    const geom::Surface* s = obj ? obj->surface() : nullptr;
    if (!s || !has_valid_point(ctx.doc)) {
        ImGui::TextWrapped("Click a control point in the 3D view to select it; it can then "
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
    ImGui::Text("%s of %s", point_name('P', i, j, s->n_u, s->n_v).c_str(), obj->name.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("(%s)", geom::name_of(s->type));
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
