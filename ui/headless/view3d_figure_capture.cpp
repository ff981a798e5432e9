#include "ui/headless/view3d_figure_capture.hpp"

#include <algorithm>

#include "ui/headless/frame_capture.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/view/drawing_picture.hpp"
#include "ui/view/picture_tap.hpp"

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
    const std::optional<Pixels> picture = capture.capture(error);
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

std::optional<Drawing> capture_panel_figure(const AppContext& ctx, FigureView view, int window_w,
                                            int window_h, float scale, std::string& error) {
    const std::string name = picture_view_name(static_cast<int>(view));
    PictureTap tap;
    CaptureSettings cs;
    cs.width = std::clamp(window_w, 16, 8192);
    cs.height = std::clamp(window_h, 16, 8192);
    cs.view = ViewMode::workstation;
    cs.scale = scale;
    FrameCapture capture(cs);
    if (!capture.error().empty()) {
        error = capture.error();
        return std::nullopt;
    }
    copy_view_state(ctx, capture.context());
    // The teaching tab that shows the view (workstation.cpp's order), brought forward.
    constexpr int tab_of[] = {-1, 0, -1, 1, 4, 2};
    if (const int tab = tab_of[static_cast<int>(view)]; tab >= 0)
        capture.context().ui.left_tab = tab;
    if (!capture.capture(error)) return std::nullopt;
    if (const Picture* p = tap.find(name)) return drawing_of(*p);
    error = "the " + name + " panel draws no Picture in this build";
    return std::nullopt;
}

} // namespace isoparm::ui
