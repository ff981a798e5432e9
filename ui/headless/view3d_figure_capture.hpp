// The 3D view as a vector figure (ui/view/figures.hpp view3d_figure) with what only GL can
// give it: the camera fitted as the window fits it (when the context's camera still needs a
// fit) and the shaded surfaces' raster under the lines, from one render of the view with the
// lines switched off. Needs a current GL context; `isoparm figure` and File > Export figure.
#pragma once

#include <optional>
#include <string>

#include "core/geom/status.hpp"
#include "ui/app_context.hpp"
#include "ui/view/figures.hpp"

namespace isoparm::ui {

// `scale`: raster pixels per point (1..4); `raster`: false for the lines alone.
geom::Expected<Drawing> capture_view3d_figure(const AppContext& ctx, const FigureOptions& o,
                                              double scale, bool raster);

// The Picture a panel draws for `view` (picture_tap.hpp), drawn as a Drawing: a headless frame
// of the whole workstation (window_w x window_h, the state of `ctx`, the view's tab brought
// forward) with a tap open. Nothing, with `error` saying why, where the panel offers no
// Picture for that view.
std::optional<Drawing> capture_panel_figure(const AppContext& ctx, FigureView view, int window_w,
                                            int window_h, float scale, std::string& error);

} // namespace isoparm::ui
