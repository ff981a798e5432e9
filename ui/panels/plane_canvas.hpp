// The background every plane canvas shares (control-point planes, curve designer): the
// panel colour, a clip to the canvas, and the world axes through the origin when in view; and
// the grid (Display > Grid) as a Picture's lines.
#pragma once

#include <imgui.h>

#include <string>

#include "ui/view/canvas_map.hpp"
#include "ui/view/picture.hpp"
#include "ui/view/snap.hpp"

namespace isoparm::ui {

// Pushes a clip rectangle: the caller pops it (ImDrawList::PopClipRect) after drawing.
inline void begin_plane_canvas(ImDrawList* dl, const PlaneMap& map, const Rect& canvas,
                               bool light) {
    const ImVec2 a(canvas.x, canvas.y), b(canvas.x + canvas.w, canvas.y + canvas.h);
    dl->AddRectFilled(a, b, light ? IM_COL32(250, 250, 250, 255) : IM_COL32(26, 28, 34, 255));
    dl->PushClipRect(a, b, true);
    const glm::dvec2 o = plane_to_pixel(map, {0, 0});
    const ImU32 axis_col = light ? IM_COL32(150, 150, 150, 255) : IM_COL32(80, 84, 96, 255);
    dl->AddLine(ImVec2(a.x, static_cast<float>(o.y)), ImVec2(b.x, static_cast<float>(o.y)),
                axis_col);
    dl->AddLine(ImVec2(static_cast<float>(o.x), a.y), ImVec2(static_cast<float>(o.x), b.y),
                axis_col);
}

// A plane canvas's Picture: the panel colour, framed.
inline Picture plane_picture(std::string view, const Rect& canvas, bool light, float scale) {
    Picture pic;
    pic.view = std::move(view);
    pic.frame = canvas;
    pic.background = light ? rgba8(250, 250, 250) : rgba8(26, 28, 34);
    pic.border = light ? rgba8(0, 0, 0) : rgba8(110, 115, 130);
    pic.border_width = 1 * scale;
    return pic;
}

// The world axes through the origin, across the canvas.
inline void plane_origin_axes(Picture& pic, const PlaneMap& map, const Rect& canvas, bool light,
                              float width = 1) {
    const glm::dvec2 o = plane_to_pixel(map, {0, 0});
    const Rgba8 axis = light ? rgba8(150, 150, 150) : rgba8(80, 84, 96);
    pic.line({canvas.x, static_cast<float>(o.y)}, {canvas.x + canvas.w, static_cast<float>(o.y)},
             axis, width);
    pic.line({static_cast<float>(o.x), canvas.y}, {static_cast<float>(o.x), canvas.y + canvas.h},
             axis, width);
}

// The grid of a plane canvas at `grid`: lines every step, every fifth stronger, the step
// written in the bottom-left corner. Nothing when it would take more than 400 lines a side.
inline void plane_grid(Picture& pic, const PlaneMap& map, const Rect& canvas, bool light,
                       const GridStep& grid) {
    const glm::vec2 a(canvas.x, canvas.y), b(canvas.x + canvas.w, canvas.y + canvas.h);
    const glm::dvec2 lo = pixel_to_plane(map, {a.x, b.y}), hi = pixel_to_plane(map, {b.x, a.y});
    const Rgba8 minor = light ? rgba8(225, 225, 230) : rgba8(38, 41, 50);
    const Rgba8 major = light ? rgba8(200, 200, 210) : rgba8(52, 56, 68);
    const GridRange gx = grid_range(grid, lo.x, hi.x), gy = grid_range(grid, lo.y, hi.y);
    if (gx.last - gx.first < 400 && gy.last - gy.first < 400) {
        for (long long q = gx.first; q <= gx.last; ++q) {
            const float x = static_cast<float>(plane_to_pixel(map, {grid_value(grid, q), 0}).x);
            pic.line({x, a.y}, {x, b.y}, q % 5 == 0 ? major : minor);
        }
        for (long long q = gy.first; q <= gy.last; ++q) {
            const float y = static_cast<float>(plane_to_pixel(map, {0, grid_value(grid, q)}).y);
            pic.line({a.x, y}, {b.x, y}, q % 5 == 0 ? major : minor);
        }
    }
    pic.fixed_label({a.x + 4, b.y - 2}, "grid " + grid_label(grid, 1),
                    light ? rgba8(120, 120, 130) : rgba8(120, 126, 140), LabelAlign::bottom_left,
                    40);
}

} // namespace isoparm::ui
