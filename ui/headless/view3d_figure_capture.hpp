// The 3D view as a vector figure (ui/view/figures.hpp view3d_figure) with what only GL can
// give it: the camera fitted as the window fits it (when the context's camera still needs a
// fit) and the shaded surfaces' raster under the lines, from one render of the view with the
// lines switched off. Needs a current GL context; `isoparm figure` and File > Export figure.
#pragma once

#include "core/geom/status.hpp"
#include "ui/app_context.hpp"
#include "ui/view/figures.hpp"

namespace isoparm::ui {

// `scale`: raster pixels per point (1..4); `raster`: false for the lines alone.
geom::Expected<Drawing> capture_view3d_figure(const AppContext& ctx, const FigureOptions& o,
                                              double scale, bool raster);

} // namespace isoparm::ui
