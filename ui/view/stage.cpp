// The stage's names, the four-view cells and a staged canvas's view transform.
#include "ui/view/stage.hpp"

#include <algorithm>

namespace isoparm::ui {

const StageViewInfo* stage_info(StageView v) {
    for (const StageViewInfo& i : stage_views)
        if (i.view == v) return &i;
    return nullptr;
}

std::optional<StageView> stage_view_named(std::string_view name) {
    for (const StageViewInfo& i : stage_views)
        if (name == i.name) return i.view;
    return std::nullopt;
}

std::string stage_view_names() {
    std::string s;
    for (const StageViewInfo& i : stage_views) {
        if (!s.empty()) s += ", ";
        s += i.name;
    }
    return s;
}

int stage_plane(StageView v) {
    const StageViewInfo* i = stage_info(v);
    return i ? i->plane : -1;
}

FourViews four_view_cells(const Rect& area, float gap) {
    const float w = std::max((area.w - gap) * 0.5f, 1.f);
    const float h = std::max((area.h - gap) * 0.5f, 1.f);
    const float x1 = area.x + w + gap, y1 = area.y + h + gap;
    FourViews f;
    f.xy = {area.x, area.y, w, h};
    f.view3d = {x1, area.y, area.x + area.w - x1, h};
    f.xz = {area.x, y1, w, area.y + area.h - y1};
    f.yz = {x1, y1, area.x + area.w - x1, area.y + area.h - y1};
    return f;
}

namespace {
glm::dvec2 centre_of(const Rect& r) {
    return {r.x + r.w * 0.5, r.y + r.h * 0.5};
}
} // namespace

glm::dvec2 view_pixel(const CanvasView& v, const Rect& canvas, const glm::dvec2& fitted) {
    const glm::dvec2 c = centre_of(canvas);
    return c + (fitted - c) * v.zoom + v.pan;
}

Rect view_rect(const CanvasView& v, const Rect& canvas, const Rect& fitted) {
    const glm::dvec2 lo = view_pixel(v, canvas, {fitted.x, fitted.y});
    return {static_cast<float>(lo.x), static_cast<float>(lo.y),
            static_cast<float>(fitted.w * v.zoom), static_cast<float>(fitted.h * v.zoom)};
}

PlaneMap view_map(const CanvasView& v, const PlaneMap& fitted) {
    // The same mapping as view_pixel(plane_to_pixel(fitted, ab)): plane_to_pixel puts
    // `center` at the canvas's centre, so the zoom divides the scale and the pan moves it.
    PlaneMap m = fitted;
    m.units_per_px = fitted.units_per_px / v.zoom;
    m.center = {fitted.center.x - v.pan.x * m.units_per_px,
                fitted.center.y + v.pan.y * m.units_per_px};
    return m;
}

void zoom_at(CanvasView& v, const Rect& canvas, const glm::dvec2& at, double factor) {
    const double z = std::clamp(v.zoom * factor, canvas_zoom_min, canvas_zoom_max);
    const double f = z / v.zoom;
    const glm::dvec2 c = centre_of(canvas);
    v.pan = (at - c) - f * (at - c - v.pan);
    v.zoom = z;
}

} // namespace isoparm::ui
