// The background every plane canvas shares (control-point planes, curve designer): the
// panel colour, a clip to the canvas, the grid (Display > Grid: lines every `step`, every fifth
// stronger, the step written in a corner) and the world axes through the origin when in view.
#pragma once

#include <imgui.h>

#include <string>

#include "ui/view/canvas_map.hpp"
#include "ui/view/snap.hpp"

namespace isoparm::ui {

// Pushes a clip rectangle: the caller pops it (ImDrawList::PopClipRect) after drawing.
inline void begin_plane_canvas(ImDrawList* dl, const PlaneMap& map, const Rect& canvas, bool light,
                               const GridStep* grid = nullptr) {
    const ImVec2 a(canvas.x, canvas.y), b(canvas.x + canvas.w, canvas.y + canvas.h);
    dl->AddRectFilled(a, b, light ? IM_COL32(250, 250, 250, 255) : IM_COL32(26, 28, 34, 255));
    dl->PushClipRect(a, b, true);
    if (grid) {
        const glm::dvec2 lo = pixel_to_plane(map, {a.x, b.y}), hi = pixel_to_plane(map, {b.x, a.y});
        const ImU32 minor = light ? IM_COL32(225, 225, 230, 255) : IM_COL32(38, 41, 50, 255);
        const ImU32 major = light ? IM_COL32(200, 200, 210, 255) : IM_COL32(52, 56, 68, 255);
        const GridRange gx = grid_range(*grid, lo.x, hi.x), gy = grid_range(*grid, lo.y, hi.y);
        if (gx.last - gx.first < 400 && gy.last - gy.first < 400) {
            for (long long q = gx.first; q <= gx.last; ++q) {
                const float x =
                    static_cast<float>(plane_to_pixel(map, {grid_value(*grid, q), 0}).x);
                dl->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), q % 5 == 0 ? major : minor);
            }
            for (long long q = gy.first; q <= gy.last; ++q) {
                const float y =
                    static_cast<float>(plane_to_pixel(map, {0, grid_value(*grid, q)}).y);
                dl->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), q % 5 == 0 ? major : minor);
            }
        }
        const std::string step = "grid " + grid_label(*grid, 1);
        dl->AddText(ImVec2(a.x + 4, b.y - ImGui::GetTextLineHeight() - 2),
                    light ? IM_COL32(120, 120, 130, 255) : IM_COL32(120, 126, 140, 255),
                    step.c_str());
    }
    const glm::dvec2 o = plane_to_pixel(map, {0, 0});
    const ImU32 axis_col = light ? IM_COL32(150, 150, 150, 255) : IM_COL32(80, 84, 96, 255);
    dl->AddLine(ImVec2(a.x, static_cast<float>(o.y)), ImVec2(b.x, static_cast<float>(o.y)),
                axis_col);
    dl->AddLine(ImVec2(static_cast<float>(o.x), a.y), ImVec2(static_cast<float>(o.x), b.y),
                axis_col);
}

} // namespace isoparm::ui
