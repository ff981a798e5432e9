// De Boor's construction for the 3D view (issue 5): the u-stage's levels over every row
// curve, then the v-stage's, coloured by level, up to the step the lecture has reached.
#pragma once

#include <glm/vec4.hpp>
#include <string>

#include "core/geom/deboor.hpp"
#include "ui/render/overlay.hpp"

namespace isoparm::ui {

// Steps: 0 the control points; 1..p_u the u-stage's levels (each row curve at u); p_u + 1 the
// column of row results (the v-stage's control polygon); then its levels up to the point
// S(u, v) at step p_u + p_v + 1. step < 0 shows everything.
struct DeBoorStepInfo {
    bool u_stage = true;
    int level = 0;
    std::string text; // "u-stage, level 2 of 3: each row curve's level 2 at u"
};
DeBoorStepInfo deboor_step_info(int step, int p_u, int p_v);

// The colour of level k (1-based) of a stage: warm for u, cool for v.
glm::vec4 deboor_level_color(bool u_stage, int level);

// Appends the construction at `step` to `out` (lines and points batches of its own).
void add_deboor_overlay(const geom::DeBoorSurfaceTrace& trace, int p_u, int p_v, int step,
                        float scale, Overlay& out);

} // namespace isoparm::ui
