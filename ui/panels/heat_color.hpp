// The heat maps' colour ramp, shared by the basis panel's square (R_ij over (u, v)) and its
// triangle (R_ijk over (r, s, t)).
#pragma once

#include <imgui.h>

#include "ui/view/basis_picture.hpp"

namespace isoparm::ui {

// The ramp of ui/view/basis_picture.hpp (heat_rgba), as ImGui's colour.
inline ImU32 heat_color(float t) {
    return heat_rgba(t);
}

} // namespace isoparm::ui
