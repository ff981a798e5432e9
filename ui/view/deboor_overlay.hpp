// De Boor's construction for the 3D view: the u-stage's levels over every row
// curve, then the v-stage's, coloured by level, up to the step the lecture has reached. The
// current step's level stands out (full colour, large points, labelled); the levels before
// it stay faint so the lecture can point at one level at a time.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "core/geom/deboor.hpp"
#include "ui/view/overlay.hpp"

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

// The name of a point of the construction, the same in the de Boor tab and the 3D view:
// level 0 of the u-stage is the control point "P2,3" (i = 2 on row j = 3); level k of row j is
// "d^k_i,j"; level 0 of the v-stage is the row result "Q3" (row j = 3) and its level k "d^k_j".
// `index` is the point's index in de Boor's triangle (first_index + position + level).
std::string deboor_point_name(bool u_stage, int level, int index, int row);

// Sizes of the construction's points and lines before the UI scale: the current level is
// drawn large, the levels already passed small and faint.
struct DeBoorSizes {
    static constexpr float current_point = 13.f;
    static constexpr float past_point = 7.f;
    static constexpr float acting_point = 11.f; // step 0's control points
    static constexpr float result_point = 18.f; // the red sphere S(u, v)
    static constexpr float current_line = 3.2f;
    static constexpr float past_line = 1.6f;
    static constexpr float past_alpha = 0.3f;
};

// Appends the construction at `step` to `out` (lines and points batches of its own).
void add_deboor_overlay(const geom::DeBoorSurfaceTrace& trace, int p_u, int p_v, int step,
                        float scale, Overlay& out);

// The labelled points of the current step's level (none when every level is shown, step < 0):
// where they are and the names the de Boor tab gives them. Points at infinity (weight 0) have
// no position and no label.
struct DeBoorLabel {
    glm::vec3 position;
    std::string text;
    glm::vec4 color;
};
std::vector<DeBoorLabel> deboor_step_labels(const geom::DeBoorSurfaceTrace& trace, int p_u, int p_v,
                                            int step);

// The (p_u + 1) x (p_v + 1) control points that act at (u, v) (their Cartesian positions;
// zero weights left out): what "zoom to the acting patch" frames.
std::vector<glm::dvec3> deboor_acting_points(const geom::DeBoorSurfaceTrace& trace, int p_v);

} // namespace isoparm::ui
