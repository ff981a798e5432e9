#include "ui/headless/view3d_figure_capture.hpp"

#include <algorithm>

#include "ui/headless/frame_capture.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

geom::Expected<Drawing> capture_view3d_figure(const AppContext& ctx, const FigureOptions& o,
                                              double scale, bool raster) {
    CaptureSettings cs;
    cs.width = std::clamp(static_cast<int>(o.width * scale), 16, 8192);
    cs.height = std::clamp(static_cast<int>(o.height * scale), 16, 8192);
    cs.view = ViewMode::view3d_only;
    cs.scale = static_cast<float>(scale);
    cs.transparent = o.transparent;
    FrameCapture capture(cs);
    if (!capture.error().empty())
        return geom::make_error_nopath(geom::ErrorCode::internal, capture.error());
    AppContext& c = capture.context();
    c.doc = ctx.doc;
    normalize_selection(c.doc);
    c.ui.camera = ctx.ui.camera;
    c.ui.camera_needs_fit = ctx.ui.camera_needs_fit;
    c.ui.zoom_after_fit = ctx.ui.zoom_after_fit;
    doc::DisplaySettings& disp = c.doc.view.display;
    disp.control_points = disp.control_net = disp.point_ids = disp.knot_curves = false;
    disp.indicator_point = disp.deboor = false;
    raster = raster && disp.style != doc::DisplayStyle::wireframe;
    if (disp.style == doc::DisplayStyle::both) disp.style = doc::DisplayStyle::shaded;
    std::string error;
    const std::optional<Picture> picture = capture.capture(error);
    if (!picture) return geom::make_error_nopath(geom::ErrorCode::internal, error);
    View3dFigureInput in;
    in.camera = c.ui.camera;
    in.deboor_step = ctx.doc.view.display.deboor ? ctx.ui.deboor.step : -1;
    if (raster) {
        DrawImage im;
        im.size = {o.width, o.height};
        im.pixels_w = picture->width;
        im.pixels_h = picture->height;
        im.rgba = picture->rgba;
        im.role = "shaded-surface";
        in.raster = std::move(im);
    }
    return view3d_figure(ctx.doc, in, o);
}

} // namespace isoparm::ui
