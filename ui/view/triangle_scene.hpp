// What the 3D view draws of a triangular Bezier patch besides its mesh: the triangular
// control net, the three isoparametric lines r, s, t = const through the indicator, and de
// Casteljau's construction on the triangle (Farin 17.3) level by level.
#pragma once

#include <optional>
#include <vector>

#include "core/geom/triangle.hpp"
#include "ui/view/overlay.hpp"

namespace isoparm::ui {

// The net's edges: b_ijk joined to b_(i-1)(j+1)k, b_(i-1)j(k+1) and b_i(j-1)(k+1), the three
// directions of the domain grid. Points at infinity (weight 0) are not joined.
void add_triangle_net(LineBatch& out, int degree, const std::vector<std::optional<glm::dvec3>>& pts,
                      const glm::vec4& color);
void add_triangle_net(LineBatch& out, const geom::TrianglePatch& t, const glm::vec4& color);

// The three curves through S(p) on which one barycentric coordinate is constant (r = p_r from
// the edge s = 0 to t = 0, and so on), `samples` points each, broken where the patch point
// does not exist.
std::vector<std::vector<glm::vec3>> triangle_iso_lines(const geom::TrianglePatch& t,
                                                       const geom::Barycentric& p, int samples);

// de Casteljau's levels at p up to `step` (0: the control points; l: level l, degree n - l;
// n: the point; < 0: all), coloured as de Boor's u-stage (deboor_level_color): the current level
// full, those passed faint.
void add_triangle_de_casteljau(const geom::TrianglePatch& t, const geom::Barycentric& p, int step,
                               float scale, Overlay& out);

} // namespace isoparm::ui
