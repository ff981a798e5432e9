// What the tracing and basis panels' domain triangles share: vertex labels, the indicator
// handle and dragging it.
#include <string>

#include "ui/panels/triangle_panels.hpp"

namespace isoparm::ui {

namespace {

float top_room(float scale) {
    return ImGui::GetTextLineHeight() * 0.5f + 2 * scale;
}

} // namespace

float triangle_label_room(float scale) {
    return top_room(scale) + ImGui::GetTextLineHeight() + 6 * scale;
}

Rect triangle_area(const Rect& box, float scale) {
    return {box.x, box.y + top_room(scale), box.w, box.h - triangle_label_room(scale)};
}

void vertex_labels(Picture& pic, const TriangleCanvas& c, int n, ImU32 color, float scale) {
    // b_n00 is r = 1 (vertex 0), b_0n0 is s = 1 (vertex 1), b_00n is t = 1 (vertex 2).
    static const char* coordinate[3] = {" (r = 1)", " (s = 1)", " (t = 1)"};
    // The coordinates too where both base labels fit side by side, else the names alone.
    const std::string widest = triangle_point_name(n, 0, n, 0) + coordinate[0];
    const bool long_labels = 2 * ImGui::CalcTextSize(widest.c_str()).x + 8 * scale <=
                             static_cast<float>(c.vertex[0].x - c.vertex[2].x);
    for (int v = 0; v < 3; ++v) {
        const int i = v == 0 ? n : 0, j = v == 1 ? n : 0;
        const std::string label =
            triangle_point_name(n, 0, i, j) + (long_labels ? coordinate[v] : "");
        const ImVec2 at = to_imvec(c.vertex[v]);
        // Below the base corners, flush with them, and beside the apex.
        if (v == 0)
            pic.fixed_label({at.x, at.y + 4 * scale}, label, color, LabelAlign::top_right, 120);
        else if (v == 2)
            pic.fixed_label({at.x, at.y + 4 * scale}, label, color, LabelAlign::top_left, 120);
        else
            pic.fixed_label({at.x + 8 * scale, at.y}, label, color, LabelAlign::center_left, 120);
    }
}

void draw_indicator_handle(ImDrawList* dl, const glm::dvec2& at, const AppContext& ctx,
                           float radius) {
    const doc::Rgba& ic = ctx.doc.colors.indicator;
    const float k = ctx.ui.scale();
    dl->AddCircleFilled(to_imvec(at), radius, ImGui::ColorConvertFloat4ToU32({ic.r, ic.g, ic.b, 1}),
                        24);
    dl->AddCircle(to_imvec(at), radius, IM_COL32(0, 0, 0, 255), 24, 1.5f * k);
}

bool barycentric_canvas(AppContext& ctx, const char* id, const Rect& box, const TriangleCanvas& c) {
    ImGui::SetCursorScreenPos(ImVec2(box.x, box.y));
    ImGui::InvisibleButton(id, ImVec2(box.w, box.h));
    if (!ImGui::IsItemActive()) return false;
    const ImVec2 m = ImGui::GetIO().MousePos;
    ctx.doc.view.barycentric = clamp_to_triangle(pixel_to_barycentric(c, {m.x, m.y}));
    ctx.ui.barycentric_refusal.clear(); // the indicator is where the pointer put it
    return true;
}

} // namespace isoparm::ui
