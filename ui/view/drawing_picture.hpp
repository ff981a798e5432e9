// A teaching view's Picture (picture.hpp: shapes and label requests, as the window draws it)
// as a Drawing, so the vector writers (ui/figure: SVG, PDF, TikZ, PNG) draw exactly what a
// panel shows: the labels placed by the one placer with the figure's font, the picture's
// frame as the page (one pixel of the view a point of the page).
#pragma once

#include "ui/view/drawing.hpp"
#include "ui/view/picture.hpp"

namespace isoparm::ui {

// `font_size`: the labels' size in points (the placer measures them at that size).
Drawing drawing_of(const Picture& p, double font_size = 9);

} // namespace isoparm::ui
