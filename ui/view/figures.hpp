// The teaching views as vector figures for slides, lecture notes and homework: the tracing
// square, the basis functions, the curve designer, de Boor's (de Casteljau's) construction,
// the homogeneous picture and the blossom, each a Drawing (ui/view/drawing.hpp) built from
// the document with the same core computations the panels use, in print colours (dark on
// white). `isoparm figure` and File > Export figure write them (ui/figure/drawing_files.hpp).
#pragma once

#include <optional>
#include <string>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/drawing.hpp"

namespace isoparm::ui {

enum class FigureView { tracing, basis, curve, deboor, homogeneous, blossom };

inline constexpr geom::EnumName<FigureView> figure_view_names[] = {
    {FigureView::tracing, "tracing"},
    {FigureView::basis, "basis"},
    {FigureView::curve, "curve"},
    {FigureView::deboor, "deboor"},
    {FigureView::homogeneous, "homogeneous"},
    {FigureView::blossom, "blossom"},
};
static_assert(geom::in_declaration_order(figure_view_names));
constexpr std::span<const geom::EnumName<FigureView>> enum_names(FigureView) {
    return figure_view_names;
}

struct FigureOptions {
    double width = 360, height = 300; // points
    double font_size = 9;             // points
    // The curve views' parameter, normalised over the curve's domain [0, 1] (the designer's t;
    // 0.4 as the designer starts, off the middle knot most curves have).
    double t = 0.4;
    // The basis view's direction on a surface (a curve has one).
    geom::Dir direction = geom::Dir::u;
    // The curve view's glyphs at t.
    bool comb = true, frenet = true;
    // de Boor's construction up to this level (-1: all).
    int deboor_level = -1;
    // The homogeneous picture's orbit (degrees).
    double yaw = -40, pitch = 22;
    bool transparent = false; // no white background
};

// The figure of `view` for the document as it is (its selection, indicator). An error names
// what the view needs and the document lacks ("the basis view needs a surface or a curve").
geom::Expected<Drawing> make_figure(const doc::Document& d, FigureView view,
                                    const FigureOptions& options);

// The curve the curve views show: the selected curve, else the first curve, else the current
// surface's isocurve u -> S(u, v) through the indicator. Its name is set for titles.
struct FigureCurve {
    geom::Curve curve;
    std::string name;
    int plane = -1; // 0 xy, 1 xz, 2 yz; -1: the best plane of its points
};
std::optional<FigureCurve> figure_curve(const doc::Document& d);

// The 3D view's lines as a vector drawing: control nets, isocurves, knot curves, de Boor's
// levels and the indicator as the view builds them (scene_builder), seen through `camera`,
// with hidden lines removed against the surfaces (a depth buffer of their tessellations,
// sampled along every segment; the control net's hidden parts dashed, as technical drawings
// show them), then sorted back to front; over `raster` (the shaded picture of the same view,
// page-sized) when given. The page is o.width x o.height points, the view's aspect.
struct View3dFigureInput {
    Camera camera;
    int deboor_step = -1;
    std::optional<DrawImage> raster;
    bool isocurves = true; // a few isocurves per surface (the figure's wireframe)
    double line_scale = 1;
};
geom::Expected<Drawing> view3d_figure(const doc::Document& d, const View3dFigureInput& in,
                                      const FigureOptions& o);

} // namespace isoparm::ui
