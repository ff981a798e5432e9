// Pieces of the curve designer panel (internal to ui/panels): the plane canvas, the knot
// strip and the basis plot, each drawn into a rectangle the panel lays out.
#pragma once

#include <functional>
#include <imgui.h>

#include "core/doc/document.hpp"
#include "ui/app_context.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/picture.hpp"

namespace isoparm::ui::curve_designer {

// The canvas plane of a curve: its own plane, or for a 3D curve the chosen view (0 xy, 1 xz,
// 2 yz, as ui::plane_axes).
int canvas_plane(const AppContext& ctx, const doc::CurveObject& c);
// The canvas framed afresh around the curve: its zoom and pan undone (the Fit button).
void fit_curve_canvas(CurveDesignerState& cd);

// The plane canvas: control polygon with labels P0..Pn, the curve, its knot points, de Boor's
// construction at the trace parameter; click to append, Ctrl+click a leg to insert, drag to
// move (one undo step), click a point to select it.
void plane_canvas(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c,
                  const Rect& canvas);

// The knot vector as ticks over the domain, values written, interior knots draggable in custom
// mode (set_knot), the trace parameter marked.
void knot_strip(AppContext& ctx, const doc::Object& obj, const doc::CurveObject& c,
                const Rect& strip);

// Every N_i(t) (R_i for rational curves) faint, the selected point's highlighted, the trace
// parameter marked with its value.
void basis_plot(AppContext& ctx, const doc::CurveObject& c, int selected, const Rect& box);

// Differential geometry of the curve (curve_analysis.cpp): the Comb / Osculating circle /
// Frenet frame check boxes; what they show on the canvas at t (px maps a 3D point to the
// canvas); curvature against t over the domain, the trace parameter marked, kappa and tau
// written.
void analysis_toggles(AppContext& ctx);
void draw_curve_analysis(const AppContext& ctx, const geom::Curve& c, double t, Picture& pic,
                         const std::function<glm::vec2(const glm::dvec3&)>& px);
void curvature_plot(AppContext& ctx, const geom::Curve& c, const Rect& box);

// Colours shared by the pieces.
ImU32 rgba(const doc::Rgba& c, float alpha = 1);
ImU32 level_color(int level, int levels); // de Boor level k of p, the final point red

} // namespace isoparm::ui::curve_designer
