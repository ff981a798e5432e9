// The control-point panel: for the selected point, three planes (xy, xz, yz) where its
// disk is dragged, exact coordinates, and the weight of rational types.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <imgui.h>
#include <string>
#include <vector>

#include "core/doc/commands.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
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

// The selected point's disk is dragged (one undo step a drag), a press on another dot selects
// that point; the net is drawn projected.
// Returns whether it moved the point (the document changed).
bool plane_canvas(AppContext& ctx, const doc::Object& obj, const ControlNet& net, int plane,
                  const Rect& canvas) {
    const PlaneAxes ax = plane_axes[plane];
    const float k = ctx.ui.scale();
    PlaneDrag& pd = ctx.ui.plane_drag;
    const PlaneMap map =
        pd.plane == plane ? pd.frozen : frame_plane(net, canvas, ax.a, ax.b, 8 * k);
    const int si = ctx.doc.view.selection.i, sj = ctx.doc.view.selection.j;
    const glm::dvec3 sel = net.points[static_cast<std::size_t>(net.find(si, sj))];
    const glm::dvec2 disk = plane_to_pixel(map, {sel[ax.a], sel[ax.b]});
    const float disk_r = 7 * k;
    bool moved = false;

    ImGui::SetCursorScreenPos(ImVec2(canvas.x, canvas.y));
    ImGui::PushID(plane);
    ImGui::InvisibleButton("##plane", ImVec2(canvas.w, canvas.h));
    report_item("cp/plane" + std::to_string(plane));
    report_point("cp/disk" + std::to_string(plane), static_cast<float>(disk.x),
                 static_cast<float>(disk.y));
    const ImVec2 m = ImGui::GetIO().MousePos;
    const glm::dvec2 mouse(m.x, m.y);
    if (ImGui::IsItemActivated()) {
        if (glm::length(mouse - disk) <= disk_r * 1.6) {
            pd.plane = plane;
            pd.frozen = map;
            pd.grab = mouse - disk;
            ctx.seal();
        } else {
            // A press on another point's dot selects that point instead.
            for (std::size_t q = 0; q < net.points.size(); ++q) {
                const glm::dvec3& p = net.points[q];
                if (glm::length(plane_to_pixel(map, {p[ax.a], p[ax.b]}) - mouse) <= 5 * k)
                    ctx.doc.view.selection = {obj.id, net.ids[q].first, net.ids[q].second};
            }
        }
    }
    if (ImGui::IsItemActive() && pd.plane == plane) {
        const glm::dvec2 ab = pixel_to_plane(pd.frozen, mouse - pd.grab);
        glm::dvec3 p = sel;
        p[ax.a] = ab.x;
        p[ax.b] = ab.y;
        if (p != sel) {
            ctx.execute(doc::move_control_point(obj.id, si, sj, p));
            moved = true;
        }
    }
    if (ImGui::IsItemDeactivated() && pd.plane == plane) {
        pd.plane = -1;
        ctx.seal();
    }
    const bool hovered = ImGui::IsItemHovered();
    ImGui::PopID();

    if (hovered) ctx.ui.stage.hovered_next = stage_plane_view(plane);
    const bool light = ctx.ui.presentation;
    Picture pic;
    pic.view = std::string("cp/") + ax.name;
    pic.frame = canvas;
    pic.background = light ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
    pic.border = light ? rgba8(0, 0, 0) : rgba8(110, 115, 130);
    pic.border_width = 1 * k;
    const glm::dvec2 o = plane_to_pixel(map, {0, 0});
    const Rgba8 axis_col = light ? rgba8(150, 150, 150) : rgba8(80, 84, 96);
    pic.line({canvas.x, static_cast<float>(o.y)}, {canvas.x + canvas.w, static_cast<float>(o.y)},
             axis_col);
    pic.line({static_cast<float>(o.x), canvas.y}, {static_cast<float>(o.x), canvas.y + canvas.h},
             axis_col);
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
    // Dots only while they stay readable; a dense net is clearer as lines alone.
    if (net.points.size() <= 144)
        for (std::size_t q = 0; q < net.points.size(); ++q)
            pic.disk(px(static_cast<int>(q)), 2.5f * k, u32(col.control_points, 0.8f));
    const bool active = pd.plane == plane;
    pic.disk(glm::vec2(disk), disk_r, u32(col.selected_point),
             active || hovered ? rgba8(255, 255, 255) : rgba8(0, 0, 0), 1.5f * k);
    pic.keep_clear.push_back({static_cast<float>(disk.x) - disk_r,
                              static_cast<float>(disk.y) - disk_r, 2 * disk_r, 2 * disk_r});
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
        if (edited && std::isfinite(value) && value != p[a]) {
            p[a] = value;
            ctx.execute(doc::move_control_point(obj.id, i, j, p));
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
        slider != w)
        ctx.execute(doc::set_weight(obj.id, i, j, slider));
    if (ImGui::IsItemDeactivated()) ctx.seal();
    if (side_by_side) ImGui::SameLine();
    ImGui::SetNextItemWidth(field);
    double typed = w;
    // Any finite value may be typed, beyond the slider's range, zero and negative included.
    if (ImGui::InputDouble("##weight_typed", &typed, 0, 0, "%.4g") && std::isfinite(typed) &&
        typed != w)
        ctx.execute(doc::set_weight(obj.id, i, j, typed));
    report_item("cp/weight");
    if (ImGui::IsItemDeactivatedAfterEdit()) ctx.seal();

    const double now = selected_point(*ctx.doc.find(obj.id), i, j).weight;
    const ImVec4 warn = ctx.ui.presentation ? ImVec4(0.7f, 0.25f, 0, 1) : ImVec4(1, 0.72f, 0.3f, 1);
    ImGui::PushStyleColor(ImGuiCol_Text,
                          now > 0 ? ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled) : warn);
    text_wrapped("%s", weight_note(now));
    ImGui::PopStyleColor();
}

// The three planes of the selected point, in a row when the panel is wide, else wrapped, with
// room left under them for the fields and the weight. False when no point is selected after
// them (a canvas's command may change the document).
bool plane_canvases(AppContext& ctx) {
    const float k = ctx.ui.scale();
    const float spacing = ImGui::GetStyle().ItemSpacing.x;
    const ImVec2 avail = ImGui::GetContentRegionAvail();
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
}

} // namespace isoparm::ui
