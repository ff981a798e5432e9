// Draws a ui/view Picture with ImGui: the window's backend of the teaching views' drawings.
#pragma once

#include <imgui.h>

#include "ui/view/picture.hpp"

namespace isoparm::ui {

// Measures text in the current ImGui font.
MeasureText imgui_measure();

// Draws the picture into `dl` (the current window's when null): its background, its shapes
// clipped to its frame, then its labels as the one placer lays them out, leader lines to
// labels moved away from their point, and the "+n" badge of dropped labels, whose hover lists
// them (a shortened label's hover shows its whole text). Reports every drawn text's rectangle
// as label/<view>/<n> (the badge as label/<view>/more), the frame as frame/<view>, and how
// many were dropped as the fact label/<view>/dropped. Returns the placement.
LabelPlacement draw_picture(const Picture& p, ImDrawList* dl = nullptr);

// A picture's pixels as ImGui's.
inline ImVec2 iv2(const glm::vec2& p) {
    return {p.x, p.y};
}
inline glm::vec2 gv2(const ImVec2& p) {
    return {p.x, p.y};
}

} // namespace isoparm::ui
