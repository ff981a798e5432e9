// The background every plane canvas shares (control-point planes, curve designer): the
// panel colour, a clip to the canvas, and the world axes through the origin when in view.
#pragma once

#include <imgui.h>

#include "ui/view/canvas_map.hpp"

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

} // namespace isoparm::ui
