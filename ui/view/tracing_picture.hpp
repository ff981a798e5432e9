// The tracing square's drawing (pure), one code for the Domain and knots panel and for a vector
// figure of the tracing view: the domain (the patch group's whole), the current patch's part,
// the knot lines, the ticks with their values and multiplicities, the indicator with its two
// isoparametric lines, the denominator's negative part and zero set, the weights at their
// Greville points, and a trimmed surface's loops with what they cut away shaded (the indicator
// drawn hollow where it leaves the kept region: no point of the trimmed surface there). Every text
// is a label of the Picture (the one placer lays them out).
#pragma once

#include <optional>
#include <vector>

#include "core/doc/document.hpp"
#include "ui/view/canvas_map.hpp"
#include "ui/view/denominator_view.hpp"
#include "ui/view/picture.hpp"

namespace isoparm::ui {

// The colours the caller's theme gives (the window's dark or presentation theme, a figure's
// print colours).
struct TracingColors {
    Rgba8 background = rgba8(28, 30, 36), border = rgba8(170, 175, 190);
    Rgba8 grid = rgba8(51, 217, 115, 140), tick = rgba8(51, 217, 115);
    Rgba8 text = rgba8(255, 255, 255), faint = rgba8(128, 128, 128);
    Rgba8 multiplicity = rgba8(255, 190, 90);
    Rgba8 indicator = rgba8(255, 51, 51), cross = rgba8(255, 51, 51, 115);
    Rgba8 current = rgba8(52, 56, 70); // the current patch's part of a group's domain
    Rgba8 negative = rgba8(230, 70, 70, 80), zero = rgba8(255, 90, 90); // the denominator
    Rgba8 weight = rgba8(255, 255, 255), weight_warning = rgba8(255, 110, 110);
    Rgba8 weight_plate = rgba8(20, 22, 28, 190);
    Rgba8 trim = rgba8(255, 200, 80), cut = rgba8(0, 0, 0, 120); // trim loops, cut-away part
};

struct TracingInput {
    Rect canvas;            // the square on screen (the visible part, on the stage)
    Rect square;            // the whole domain, seen through the canvas's zoom and pan
    float label_w = 40;     // the strip left of the canvas for the v values
    float label_h = 40;     // the strip below it for the u values and multiplicities
    float scale = 1;        // presentation mode times HiDPI: widths, radii, gaps
    float line_height = 15; // the font's line height
    TracingColors colors;
    bool weights = false; // each weight at its Greville point (rational surfaces)
    const DenominatorView* denominator = nullptr; // updated for the surface; null: not shown
    // A knot tick being dragged: its direction and the index of its run's first copy.
    std::optional<std::pair<geom::Dir, int>> held;
};

struct TracingPicture {
    Picture picture;
    std::vector<KnotTick> ticks_u, ticks_v;
    std::vector<double> px_u, px_v; // each tick's pixel along its edge (the knot handles)
    glm::vec2 indicator{0};         // where the indicator is drawn
    bool indicator_cut = false;     // the indicator lies in the part a trim cuts away
};

// The drawing of `obj`'s tracing square (a spline surface; the document gives the patch group
// and the indicator). The Picture is named "tracing"; its frame covers the strips and the
// canvas.
TracingPicture tracing_picture(const doc::Document& d, const doc::Object& obj,
                               const TracingInput& in);

} // namespace isoparm::ui
