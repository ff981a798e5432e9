// The Homogeneous tab: a rational curve is the central projection of a polynomial one. The
// selected curve (or the current surface's isocurve through the indicator, seen in a coordinate
// plane) is lifted to (w a, w b, w) with its homogeneous control polygon; rays from the origin
// through each lifted control point meet the plane w = 1 at the control point itself, and the
// lifted curve projects to the curve. DesignMentor's NURBS add-on showed this for planar curves
// only; here any isocurve of a surface can be lifted too. Drag to turn the picture.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/common.hpp>
#include <imgui.h>
#include <string>
#include <utility>

#include "core/geom/knots.hpp"
#include "core/geom/rational_picture.hpp"
#include "core/geom/status.hpp"
#include "ui/panels/canvas_hint.hpp"
#include "ui/panels/curve_designer.hpp"
#include "ui/panels/flow.hpp"
#include "ui/panels/panels.hpp"
#include "ui/panels/picture_draw.hpp"
#include "ui/panels/stage_controls.hpp"
#include "ui/theme.hpp"
#include "ui/ui_report.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/homogeneous_scene.hpp"

namespace isoparm::ui {

namespace {

constexpr std::array<std::array<int, 2>, 3> plane_axes{{{0, 1}, {0, 2}, {1, 2}}};

// What is lifted: the curve, the coordinates seen, the traced parameter and a caption.
struct Lifted {
    geom::Curve curve;
    std::array<int, 2> axes{0, 1};
    double t = 0;
    std::string caption;
    bool own_plane = false; // a planar curve is seen in its own plane (no plane choice)
};

std::array<int, 2> seen_in(const HomogeneousState& hs, const geom::Curve& c) {
    return hs.plane < 0 ? best_plane(c)
                        : plane_axes[static_cast<std::size_t>(std::min(hs.plane, 2))];
}

std::string axes_name(std::array<int, 2> axes) {
    return {"xyz"[axes[0]], "xyz"[axes[1]]};
}

std::optional<Lifted> chosen_curve(AppContext& ctx, std::string& why_not) {
    HomogeneousState& hs = ctx.ui.homogeneous;
    const doc::Object* sel = ctx.doc.selected();
    if (sel && sel->curve_object()) {
        const doc::CurveObject& co = *sel->curve_object();
        Lifted l;
        l.curve = co.curve;
        l.own_plane = co.plane != doc::CurvePlane::free3d;
        l.axes =
            l.own_plane ? plane_axes[static_cast<std::size_t>(co.plane)] : seen_in(hs, l.curve);
        l.t = ctx.ui.curve.trace_param(l.curve);
        l.caption = sel->name + " in the " + axes_name(l.axes) + " plane";
        return l;
    }
    const doc::Object* obj = nullptr;
    const geom::Surface* s = current_surface(ctx.doc, &obj);
    if (!s) {
        why_not = "Select a curve, or make a surface: its isocurve through the indicator is "
                  "lifted here.";
        return std::nullopt;
    }
    const glm::dvec2 uv = indicator_params(ctx.doc, *obj);
    // Along u: v is held at the indicator's v (the curve S(u, v*)), traced at the indicator's u.
    const bool along_u = hs.isocurve == 0;
    const auto iso =
        geom::isocurve(*s, along_u ? geom::Dir::v : geom::Dir::u, along_u ? uv.y : uv.x);
    if (!iso) {
        char text[160];
        std::snprintf(text, sizeof text,
                      "The isocurve %s = %s has a control point at infinity (its weights sum "
                      "to 0 there): move the indicator.",
                      along_u ? "v" : "u", geom::format_short(along_u ? uv.y : uv.x).c_str());
        why_not = text;
        return std::nullopt;
    }
    Lifted l;
    l.curve = *iso;
    l.axes = seen_in(hs, l.curve);
    l.t = along_u ? uv.x : uv.y;
    char text[160];
    std::snprintf(text, sizeof text, "%s's isocurve %s = %s, seen in %s", obj->name.c_str(),
                  along_u ? "v" : "u", geom::format_short(along_u ? uv.y : uv.x).c_str(),
                  axes_name(l.axes).c_str());
    l.caption = text;
    return l;
}

// The drawn part of the ray from the origin through a lifted point q = w (a, b, 1) to its
// projection p = (a, b, 1): from the origin to the further of the two when w > 0; through the
// origin from q to p when w < 0 (q lies below the origin, on the far side of the centre).
std::pair<glm::dvec3, glm::dvec3> ray_ends(const glm::dvec3& q, const glm::dvec3& p) {
    if (q.z < 0) return {q, p};
    return {glm::dvec3(0), q.z > 1 ? q : p};
}

void draw_lifted(AppContext& ctx, const Lifted& l, const HomogeneousScene& h, const Rect& box,
                 const CanvasView& cv) {
    HomogeneousState& hs = ctx.ui.homogeneous;
    const float k = ctx.ui.scale();
    const bool light = ctx.ui.presentation;
    Picture pic;
    pic.view = "homogeneous";
    pic.frame = box;
    pic.background = light ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
    pic.style.offset = 5 * k;

    // Fit the turned picture's box (its eight corners) into the canvas, then zoom.
    glm::dvec2 lo{1e300}, hi{-1e300};
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 p(c & 1 ? h.hi.x : h.lo.x, c & 2 ? h.hi.y : h.lo.y,
                           c & 4 ? h.hi.z : h.lo.z);
        const glm::dvec3 q = orbit_project(p, hs.yaw, hs.pitch);
        lo = glm::min(lo, glm::dvec2(q));
        hi = glm::max(hi, glm::dvec2(q));
    }
    const glm::dvec2 span = glm::max(hi - lo, glm::dvec2(1e-9));
    const double scale = 0.9 * std::min(box.w / span.x, box.h / span.y) * hs.zoom;
    const glm::dvec2 mid = 0.5 * (lo + hi);
    auto px = [&](const glm::dvec3& p) {
        const glm::dvec3 q = orbit_project(p, hs.yaw, hs.pitch);
        const glm::dvec2 fitted(box.x + box.w / 2 + (q.x - mid.x) * scale,
                                box.y + box.h / 2 - (q.y - mid.y) * scale);
        return glm::vec2(view_pixel(cv, box, fitted));
    };

    // The plane w = 1, where the rational curve lives.
    const glm::vec2 corners[4] = {
        px({h.plane_lo.x, h.plane_lo.y, 1}), px({h.plane_hi.x, h.plane_lo.y, 1}),
        px({h.plane_hi.x, h.plane_hi.y, 1}), px({h.plane_lo.x, h.plane_hi.y, 1})};
    pic.polygon({corners, corners + 4}, light ? rgba8(255, 200, 120, 60) : rgba8(255, 190, 90, 40));
    pic.polyline({corners, corners + 4},
                 light ? rgba8(200, 120, 30, 200) : rgba8(255, 190, 90, 140), 1.2f * k, true);
    pic.label(corners[2], "w = 1", light ? rgba8(160, 90, 10) : rgba8(255, 190, 90), 30);

    // Axes from the origin: the rays' centre.
    const std::string a_name(1, "xyz"[l.axes[0]]), b_name(1, "xyz"[l.axes[1]]);
    const double axis_len = std::max({h.hi.x, h.hi.y, h.hi.z, 1.0}) * 1.05;
    const Rgba8 axis_cols[3] = {rgba8(220, 80, 80), rgba8(80, 190, 80), rgba8(90, 130, 255)};
    for (int c = 0; c < 3; ++c) {
        glm::dvec3 e(0);
        e[c] = axis_len;
        const glm::vec2 tip = px(e);
        pic.line(px({0, 0, 0}), tip, axis_cols[c], 1.5f * k);
        pic.label(tip, c == 2 ? "w" : c == 0 ? "w" + a_name : "w" + b_name, axis_cols[c], 40);
    }
    pic.disk(px({0, 0, 0}), 3.5f * k, ImGui::GetColorU32(ImGuiCol_Text));

    // Rays: from the origin through each lifted control point to the plane w = 1 (a negative
    // weight puts the lifted point below the origin; its ray still passes through it).
    const Rgba8 ray = light ? rgba8(110, 110, 120, 150) : rgba8(170, 175, 190, 110);
    for (std::size_t i = 0; i < h.lifted_points.size(); ++i) {
        if (h.weights[i] == 0) continue; // (w P, 0) = 0: the point has no say, no ray
        const auto [from, to] = ray_ends(h.lifted_points[i], h.projected_points[i]);
        pic.line(px(from), px(to), ray, 1.0f * k);
    }
    // The rational curve on w = 1 and its control polygon there.
    const Rgba8 flat = light ? rgba8(200, 110, 20) : rgba8(255, 175, 70);
    for (const auto& run : h.projected_curve) {
        std::vector<glm::vec2> pts;
        for (const glm::dvec3& p : run) pts.push_back(px(p));
        pic.polyline(std::move(pts), flat, 2.6f * k);
    }
    for (const glm::dvec3& p : h.projected_points) pic.disk(px(p), 3 * k, flat);
    // The polynomial curve in homogeneous space and its control polygon.
    const Rgba8 lifted = light ? rgba8(20, 100, 200) : rgba8(110, 190, 255);
    std::vector<glm::vec2> poly;
    for (const glm::dvec3& p : h.lifted_points) poly.push_back(px(p));
    pic.polyline(poly, light ? rgba8(60, 60, 70, 200) : rgba8(200, 200, 210, 170), 1.2f * k);
    std::vector<glm::vec2> curve;
    for (const glm::dvec3& p : h.lifted_curve) curve.push_back(px(p));
    pic.polyline(std::move(curve), lifted, 2.6f * k);
    const Rgba8 text = ImGui::GetColorU32(ImGuiCol_Text);
    const Rgba8 warn = ImGui::ColorConvertFloat4ToU32(error_text_color());
    const Rgba8 plate = light ? rgba8(255, 255, 255, 190) : rgba8(26, 28, 34, 190);
    for (std::size_t i = 0; i < h.lifted_points.size(); ++i) {
        pic.disk(poly[i], 4.5f * k, lifted);
        if (!hs.labels) continue;
        // Weights other than 1 first: a revolved profile's w = 1 and w = 0.707 alternate.
        const double w = h.weights[i];
        LabelRequest& r = pic.label(poly[i], "w=" + geom::format_short(w, 3), w <= 0 ? warn : text,
                                    w != 1 ? 20 : 10);
        r.plate = plate;
        r.tooltip = "w" + std::to_string(i) + " = " + geom::format_number(w);
    }
    // The point at t: lifted, projected, and the ray between them.
    if (h.lifted_at_t) {
        const Rgba8 red = rgba8(235, 60, 60);
        const glm::dvec3 q = *h.lifted_at_t;
        if (h.projected_at_t) {
            const auto [from, to] = ray_ends(q, *h.projected_at_t);
            pic.line(px(from), px(to), red, 1.4f * k);
            pic.disk(px(*h.projected_at_t), 5 * k, red);
        }
        pic.disk(px(q), 6 * k, 0, red, 2 * k);
    }
    draw_picture(pic);
}

} // namespace

namespace {

// Which curve is lifted and how it is seen: two small combos rather than rows of radio
// buttons, each control on the line while it fits.
void homogeneous_controls(AppContext& ctx, const std::optional<Lifted>& l, bool surface_source) {
    HomogeneousState& hs = ctx.ui.homogeneous;
    const float combo_w = ImGui::CalcTextSize("along u").x + ImGui::GetFrameHeight() * 2;
    if (surface_source) {
        const char* iso_names[] = {"along u", "along v"};
        ImGui::SetNextItemWidth(combo_w);
        const bool open = ImGui::BeginCombo("##isocurve", iso_names[hs.isocurve == 1 ? 1 : 0]);
        report_item("homogeneous/isocurve");
        if (open) {
            for (int k = 0; k < 2; ++k) {
                if (ImGui::Selectable(iso_names[k], hs.isocurve == k)) hs.isocurve = k;
                report_item(std::string("homogeneous/isocurve/") + iso_names[k]);
            }
            ImGui::EndCombo();
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "The current surface's isocurve through the indicator that is lifted");
    }
    if (!l || !l->own_plane) {
        const char* planes[] = {"best", "xy", "xz", "yz"};
        int choice = hs.plane + 1;
        if (surface_source) same_line_if_fits(combo_w);
        ImGui::SetNextItemWidth(combo_w);
        if (ImGui::Combo("##plane", &choice, planes, 4)) hs.plane = choice - 1;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("The coordinates seen (best: the two largest extents of the "
                              "control points)");
    }
    same_line_if_fits(toggle_width("Weights"));
    ImGui::Checkbox("Weights", &hs.labels);
    same_line_if_fits(ImGui::CalcTextSize("Reset").x + ImGui::GetStyle().FramePadding.x * 2);
    if (ImGui::SmallButton("Reset")) hs = HomogeneousState{hs.isocurve, hs.plane};
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Turn and zoom the picture back");
}

} // namespace

void draw_homogeneous_panel(AppContext& ctx) {
    note_hovered_view(ctx, StageView::homogeneous);
    HomogeneousState& hs = ctx.ui.homogeneous;
    const float k = ctx.ui.scale();
    std::string why_not;
    const std::optional<Lifted> l = chosen_curve(ctx, why_not);
    const doc::Object* sel = ctx.doc.selected();
    const bool surface_source = !(sel && sel->curve_object());
    if (!l) {
        homogeneous_controls(ctx, l, surface_source);
        text_wrapped("%s", why_not.c_str());
        return;
    }
    const HomogeneousScene h = homogeneous_scene(l->curve, l->axes, l->t);
    // The picture first: a projector's short slot shows it whole, and the controls below it
    // scroll if they must.
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float below =
        ImGui::GetFrameHeightWithSpacing() * 2 + ImGui::GetTextLineHeightWithSpacing() * 2;
    const Rect box{ImGui::GetCursorScreenPos().x, ImGui::GetCursorScreenPos().y, avail.x,
                   std::max({avail.y - below, avail.y * 0.5f, 60 * k})};
    ImGui::InvisibleButton("##homogeneous", ImVec2(box.w, box.h));
    report_item("homogeneous/canvas");
    // On the stage the wheel zooms about the pointer and a right-drag pans (canvas_view);
    // in the tab the wheel zooms the picture about its centre.
    const bool staged = on_stage(ctx, StageView::homogeneous);
    const CanvasView cv = canvas_view(ctx, "homogeneous", box);
    if (ImGui::IsItemActive() && ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        const ImVec2 d = ImGui::GetIO().MouseDelta;
        hs.yaw += d.x * 0.4;
        // The picture turns over the top no further than looking straight down.
        hs.pitch = std::clamp(hs.pitch + d.y * 0.4, -89.0, 89.0);
    }
    if (!staged && ImGui::IsItemHovered() && ImGui::GetIO().MouseWheel != 0)
        hs.zoom = std::clamp(hs.zoom * std::pow(1.15, ImGui::GetIO().MouseWheel), 0.2, 20.0);
    if (!ImGui::IsItemActive() && canvas_hint_due(ctx.ui))
        ImGui::SetTooltip("Drag to turn the picture, wheel to zoom");
    draw_lifted(ctx, *l, h, box, cv);
    if (h.lifted_at_t) {
        const glm::dvec3 q = *h.lifted_at_t;
        text_wrapped("t = %s: C^w = (%s, %s, %s), w = %s", geom::format_short(h.t).c_str(),
                     geom::format_short(q.x).c_str(), geom::format_short(q.y).c_str(),
                     geom::format_short(q.z).c_str(), geom::format_short(q.z).c_str());
    }
    text_wrapped("%s", l->caption.c_str());
    same_line_if_fits(ImGui::CalcTextSize("(?)").x);
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered())
        wrapped_tooltip("C(t) = C^w(t) / w(t). The blue curve is a polynomial B-spline in (w x, "
                        "w y, w) with the control points (w_i x_i, w_i y_i, w_i); projected from "
                        "the origin onto the plane w = 1 it is the orange rational curve. Each "
                        "grey ray joins the origin, a lifted control point and the control point "
                        "itself on w = 1; a negative weight puts the lifted point below the "
                        "origin.");
    homogeneous_controls(ctx, l, surface_source);
    report_fact("homogeneous/control_points", static_cast<double>(h.lifted_points.size()));
    report_fact("homogeneous/yaw", hs.yaw);
    report_fact("homogeneous/isocurve", surface_source ? hs.isocurve : -1);
}

} // namespace isoparm::ui
