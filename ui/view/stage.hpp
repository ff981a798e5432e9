// The stage (pure): which teaching view takes the main area at full size, the four-view
// layout's cells, and a staged canvas's zoom and pan.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <glm/vec2.hpp>

#include "ui/view/canvas_map.hpp"
#include "ui/view/layout.hpp"

namespace isoparm::ui {

// The teaching views that can take the stage (View > Stage, the button in a view's header, T
// over the view, `isoparm --stage NAME`).
enum class StageView {
    none,
    tracing,     // the tracing square (or a triangle's domain triangle)
    basis,       // the basis functions: heat map and N_i(u), N_j(v)
    deboor,      // de Boor's construction: the 3D view beside the step list
    plane_xy,    // the control point in the xy plane
    plane_xz,    // ... in xz
    plane_yz,    // ... in yz
    curve,       // the curve designer's canvas
    homogeneous, // the Homogeneous tab
    blossom,     // the Blossom tab
    multires,    // the Multires tab
    continuity   // the Continuity tab
};

struct StageViewInfo {
    StageView view;
    const char* name;  // on the command line and in the UI report (stage/<name>)
    const char* title; // in the menu and the stage's header
    int plane = -1;    // the coordinate plane a plane view shows (0 xy, 1 xz, 2 yz)
};

inline constexpr std::array<StageViewInfo, 11> stage_views{{
    {StageView::tracing, "tracing", "Tracing square"},
    {StageView::basis, "basis", "Basis functions"},
    {StageView::deboor, "deboor", "de Boor"},
    {StageView::plane_xy, "xy", "xy plane", 0},
    {StageView::plane_xz, "xz", "xz plane", 1},
    {StageView::plane_yz, "yz", "yz plane", 2},
    {StageView::curve, "curve", "Curve designer"},
    {StageView::homogeneous, "homogeneous", "Homogeneous"},
    {StageView::blossom, "blossom", "Blossom"},
    {StageView::multires, "multires", "Multires"},
    {StageView::continuity, "continuity", "Continuity"},
}};

const StageViewInfo* stage_info(StageView v);
std::optional<StageView> stage_view_named(std::string_view name);
// "tracing, basis, ..., continuity": for the command line's error.
std::string stage_view_names();
// The plane (0 xy, 1 xz, 2 yz) a plane view shows; -1 for the others.
int stage_plane(StageView v);

// The four-view layout, as modelers have it: xy (top) upper left, the 3D view upper right,
// xz (front) lower left, yz (side) lower right; four cells of one size filling `area`.
struct FourViews {
    Rect xy, view3d, xz, yz;
    Rect plane(int p) const { return p == 0 ? xy : p == 1 ? xz : yz; }
};
FourViews four_view_cells(const Rect& area, float gap);

// A staged canvas's zoom and pan: the picture fitted to the canvas, then scaled by `zoom`
// about the canvas's centre and moved by `pan` pixels. Fit (F) is the default view.
struct CanvasView {
    double zoom = 1;
    glm::dvec2 pan{0};
    bool operator==(const CanvasView&) const = default;
};
constexpr double canvas_zoom_min = 0.25, canvas_zoom_max = 64;

// A pixel of the fitted picture, seen through the view.
glm::dvec2 view_pixel(const CanvasView& v, const Rect& canvas, const glm::dvec2& fitted);
// A rectangle of the fitted picture (the tracing square), seen through the view.
Rect view_rect(const CanvasView& v, const Rect& canvas, const Rect& fitted);
// A plane canvas's fitted mapping, seen through the view (same canvas, zoomed and moved).
PlaneMap view_map(const CanvasView& v, const PlaneMap& fitted);
// The wheel at `at`: zoom by `factor`, keeping the point under the pointer where it is.
void zoom_at(CanvasView& v, const Rect& canvas, const glm::dvec2& at, double factor);

} // namespace isoparm::ui
