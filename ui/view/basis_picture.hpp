// The Basis tab's drawings (pure), one code for the panel and for a figure: the basis functions
// N_k(t) of a knot vector over its domain with one highlighted and the parameter marked, and a
// surface's R_ij as a heat map over the domain with its support and the indicator.
#pragma once

#include <string>
#include <vector>

#include "core/geom/types.hpp"
#include "ui/view/picture.hpp"
#include "ui/view/stage.hpp"

namespace isoparm::ui {

// The heat maps' colour ramp (dark blue, purple, orange, yellow) for t in [0, 1]; negative
// values (negative weights) take a separate cyan ramp so that the sign is never ambiguous.
Rgba8 heat_rgba(float t);

struct PlotColors {
    Rgba8 background = rgba8(26, 28, 34), border = rgba8(110, 110, 128);
    Rgba8 faint = rgba8(110, 115, 135);        // the other functions
    Rgba8 strong = rgba8(255, 64, 64);         // the selected point's function
    Rgba8 parameter = rgba8(255, 51, 51, 230); // the indicator's line
    Rgba8 title = rgba8(128, 128, 128);
};

// N_k(t), k = 0 .. n - 1, of knots U (degree p) over [U[p], U[n]] in `box`, N_index strong
// (index < 0: none), the line at parameter t, titled `title` (e.g. "N2(u), degree 3"); seen
// through the stage's zoom and pan `view`. The Picture is named `name`.
Picture basis_curves_picture(const geom::Knots& U, int p, int n, int index, double t,
                             const std::string& title, const std::string& name, const Rect& box,
                             const CanvasView& view, float scale, float line_height,
                             const PlotColors& colors);

// R_ij sampled on a resolution x resolution grid (row-major, v from the top; NaN undefined),
// normalised by max_value, in `square` (the canvas seen through its view) clipped to `canvas`,
// with the support's box [u0, u1] x [v0, v1] and the indicator at `at` (all normalised to the
// domain), the function's name in a corner. Named "basis_heat".
struct HeatInput {
    Rect canvas, square;
    const std::vector<float>* values = nullptr;
    int resolution = 0;
    float max_value = 0;
    double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
    glm::dvec2 at{0.5};
    std::string name;
    float scale = 1;
    Rgba8 border = rgba8(110, 110, 128), indicator = rgba8(255, 51, 51);
};
Picture heat_picture(const HeatInput& in);

} // namespace isoparm::ui
