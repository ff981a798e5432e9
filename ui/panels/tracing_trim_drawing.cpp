#include "ui/panels/tracing_trim_drawing.hpp"

#include <cmath>
#include <imgui.h>
#include <vector>

#include "core/doc/patches.hpp"
#include "core/geom/evaluate.hpp"
#include "ui/trim_actions.hpp"
#include "ui/view/canvas_map.hpp"

namespace isoparm::ui {

namespace {

// A click this near the first corner (in pixels at scale 1) closes the loop.
constexpr float close_radius = 9;

// A corner in the surface's (u, v) on the square, and back: the square shows the patch
// group's whole domain (doc::tracing_domain), of which the surface may own a part.
ImVec2 corner_pixel(const AppContext& ctx, const doc::Object& obj, const Rect& square,
                    glm::dvec2 uv) {
    const geom::ParamRect all = doc::tracing_domain(ctx.doc, obj);
    const glm::dvec2 p =
        domain_to_pixel(square, {normalize_param(all.u, uv.x), normalize_param(all.v, uv.y)});
    return {float(p.x), float(p.y)};
}

glm::dvec2 pixel_corner(const AppContext& ctx, const doc::Object& obj, const Rect& square,
                        ImVec2 pixel) {
    const geom::ParamRect all = doc::tracing_domain(ctx.doc, obj);
    const glm::dvec2 n = pixel_to_domain(square, {pixel.x, pixel.y});
    return {denormalize_param(all.u, n.x), denormalize_param(all.v, n.y)};
}

} // namespace

bool drawing_loop_on(AppContext& ctx, const doc::Object& obj) {
    const TrimDrawing& d = ctx.ui.trim_drawing;
    if (!d.active()) return false;
    if (d.object != obj.id) {
        cancel_loop_drawing(ctx);
        return false;
    }
    return true;
}

void loop_drawing_click(AppContext& ctx, const doc::Object& obj, const Rect& square) {
    if (!ImGui::IsItemClicked(ImGuiMouseButton_Left)) return;
    const ImVec2 m = ImGui::GetIO().MousePos;
    const TrimDrawing& d = ctx.ui.trim_drawing;
    if (d.corners.size() >= 3) {
        const ImVec2 first = corner_pixel(ctx, obj, square, d.corners.front());
        if (std::hypot(m.x - first.x, m.y - first.y) <= close_radius * ctx.ui.scale()) {
            close_drawn_loop(ctx);
            return;
        }
    }
    add_loop_corner(ctx, pixel_corner(ctx, obj, square, m));
}

void draw_loop_in_progress(const AppContext& ctx, const doc::Object& obj, const Rect& square,
                           const Rect& canvas) {
    const TrimDrawing& d = ctx.ui.trim_drawing;
    if (d.object != obj.id || d.corners.empty()) return;
    const float k = ctx.ui.scale();
    const ImU32 line = IM_COL32(255, 200, 80, 255), dot = IM_COL32(255, 235, 180, 255);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(ImVec2(canvas.x, canvas.y), ImVec2(canvas.x + canvas.w, canvas.y + canvas.h),
                     true);
    std::vector<ImVec2> px;
    for (const glm::dvec2& c : d.corners) px.push_back(corner_pixel(ctx, obj, square, c));
    const bool smooth = ctx.ui.smooth_loops && d.corners.size() >= 3;
    // Smooth: the corners are a control polygon (thin) and the loop they make is drawn.
    dl->AddPolyline(px.data(), int(px.size()), line, ImDrawFlags_None, (smooth ? 1.0f : 2.5f) * k);
    if (smooth) {
        std::vector<ImVec2> curve;
        for (const geom::Curve& piece : drawn_loop(d.corners, true).curves)
            for (int s = 0; s < 16; ++s)
                if (auto p = geom::curve_point(piece, s / 16.0))
                    curve.push_back(corner_pixel(ctx, obj, square, {p->x, p->y}));
        dl->AddPolyline(curve.data(), int(curve.size()), line, ImDrawFlags_Closed, 2.5f * k);
    }
    // The edge the next click (or Enter) would add, dashed-looking by its thinner line.
    const ImVec2 m = ImGui::GetIO().MousePos;
    if (canvas.contains(m.x, m.y)) dl->AddLine(px.back(), m, line, 1.0f * k);
    for (std::size_t i = 0; i < px.size(); ++i)
        dl->AddCircleFilled(px[i], (i == 0 ? 5.f : 3.5f) * k, dot);
    // The first corner ringed once the loop can close on it.
    if (px.size() >= 3) dl->AddCircle(px.front(), close_radius * k, line, 0, 1.5f * k);
    dl->PopClipRect();
}

} // namespace isoparm::ui
