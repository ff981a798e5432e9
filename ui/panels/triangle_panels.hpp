// The teaching panels for a selected triangular Bezier patch (Farin, "Curves and Surfaces for
// CAGD", ch. 17): the tracing panel's domain triangle, de Casteljau's construction in the de
// Boor tab, and the Bernstein basis in the Basis tab. Each panel calls its triangle version
// when selected_triangle() finds one; the computations are in ui/view/triangle_domain.
#pragma once

#include <imgui.h>

#include "ui/app_context.hpp"
#include "ui/view/picture.hpp"
#include "ui/view/triangle_domain.hpp"

namespace isoparm::ui {

void draw_triangle_tracing(AppContext& ctx, const doc::Object& obj, const geom::TrianglePatch& t);
void draw_triangle_casteljau(AppContext& ctx, const doc::Object& obj, const geom::TrianglePatch& t);
void draw_triangle_basis(AppContext& ctx, const doc::Object& obj, const geom::TrianglePatch& t);

// The de Boor tab's step row (|<, <, Play, >, All; deboor_panel.cpp), for de Casteljau's
// construction too: `last` is the last step's number.
void deboor_step_buttons(AppContext& ctx, int last);

// Shared by the tracing and basis canvases (ui/panels/triangle_canvas.cpp).

inline ImVec2 to_imvec(const glm::dvec2& p) {
    return {static_cast<float>(p.x), static_cast<float>(p.y)};
}

// The part of `box` the triangle may fill: the base's labels take a line below it, the
// apex's half a line above (its label sits beside it).
Rect triangle_area(const Rect& box, float scale);
// The vertical room triangle_area leaves out.
float triangle_label_room(float scale);

// The three vertices named by their control point and coordinate ("b300 (r = 1)"): below the
// base corners, flush with them, and beside the apex, as fixed labels of the canvas's picture.
void vertex_labels(Picture& pic, const TriangleCanvas& c, int n, ImU32 color, float scale);

// The indicator (r, s, t) as the tracing square draws (u, v): a filled disc with a black ring.
void draw_indicator_handle(ImDrawList* dl, const glm::dvec2& at, const AppContext& ctx,
                           float radius);

// An invisible button over `box`: pressing anywhere in it moves the indicator to the pointer,
// clamped to the triangle (view state, not undoable, as on the square), and so does a drag.
// Returns whether it is held.
bool barycentric_canvas(AppContext& ctx, const char* id, const Rect& box, const TriangleCanvas& c);

} // namespace isoparm::ui
