// The caption box's place (caption_place.hpp).
#include "ui/view/caption_place.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

#include "core/doc/point_set.hpp"
#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/triangle.hpp"
#include "ui/view/doc_access.hpp"

namespace isoparm::ui {

namespace {

// Points of the object that bound what is drawn of it: a grid of surface points (the control
// net can lie far from a rational surface), a curve's points, a triangle's net, an implicit
// surface's box corners; and the control points where they are drawn.
std::vector<glm::dvec3> outline_points(const doc::Object& o, const doc::DisplaySettings& show) {
    std::vector<glm::dvec3> out;
    if (show.control_points || show.control_net) {
        const std::span<const glm::dvec3> net = doc::control_points_of(o.shape);
        out.assign(net.begin(), net.end());
    }
    constexpr int n = 8;
    std::visit(
        doc::overloaded{
            [&](const doc::SurfaceObject& so) {
                const geom::Surface& s = so.surface;
                const geom::ParamRect d = geom::domain(s);
                for (int a = 0; a <= n; ++a)
                    for (int b = 0; b <= n; ++b)
                        if (auto p = geom::surface_point(s, d.u.lo + (d.u.hi - d.u.lo) * a / n,
                                                         d.v.lo + (d.v.hi - d.v.lo) * b / n))
                            out.push_back(*p);
            },
            [&](const doc::CurveObject& co) {
                const geom::Interval d = geom::domain(co.curve);
                for (int a = 0; a <= 4 * n; ++a)
                    if (auto p = geom::curve_point(co.curve, d.lo + (d.hi - d.lo) * a / (4 * n)))
                        out.push_back(*p);
            },
            [&](const doc::ImplicitObject& f) {
                for (int k = 0; k < 8; ++k)
                    out.push_back({k & 1 ? f.hi.x : f.lo.x, k & 2 ? f.hi.y : f.lo.y,
                                   k & 4 ? f.hi.z : f.lo.z});
            },
            [&](const doc::TriangleObject& t) {
                out.insert(out.end(), t.patch.points.begin(), t.patch.points.end());
            },
        },
        o.shape);
    return out;
}

std::optional<Rect> screen_box(const std::vector<glm::dvec3>& pts, const glm::dmat4& m,
                               const Viewport& vp) {
    float x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const glm::dvec3& p : pts) {
        const Projected q = project(m, vp, p);
        if (!q.visible) continue;
        x0 = std::min(x0, static_cast<float>(q.pixel.x));
        y0 = std::min(y0, static_cast<float>(q.pixel.y));
        x1 = std::max(x1, static_cast<float>(q.pixel.x));
        y1 = std::max(y1, static_cast<float>(q.pixel.y));
    }
    if (x0 > x1) return std::nullopt;
    return Rect{x0, y0, x1 - x0, y1 - y0};
}

std::optional<glm::dvec3> selected_point(const doc::Document& d) {
    const doc::Object* o = d.selected();
    const doc::Selection& s = d.view.selection;
    if (!o || !s.has_point() || !doc::has_control_point(o->shape, s.i, s.j)) return std::nullopt;
    return doc::position_of(o->shape, {s.i, s.j});
}

} // namespace

std::vector<glm::dvec3> focus_points(const doc::Document& d) {
    std::vector<glm::dvec3> out;
    const doc::Object* sel = d.selected();
    for (const doc::Object& o : d.objects) {
        if (!o.visible || (sel && &o != sel)) continue;
        const std::vector<glm::dvec3> pts = outline_points(o, d.view.display);
        out.insert(out.end(), pts.begin(), pts.end());
    }
    if (auto p = selected_point(d)) out.push_back(*p);
    return out;
}

Rect free_beside(const Rect& view, const Rect& box) {
    const Rect above{view.x, view.y, view.w, std::max(0.f, box.y - view.y)};
    const Rect below{view.x, box.y + box.h, view.w,
                     std::max(0.f, view.y + view.h - (box.y + box.h))};
    const Rect left{view.x, view.y, std::max(0.f, box.x - view.x), view.h};
    const Rect right{box.x + box.w, view.y, std::max(0.f, view.x + view.w - (box.x + box.w)),
                     view.h};
    Rect best = above;
    for (const Rect& r : {below, left, right})
        if (r.w * r.h > best.w * best.h) best = r;
    return best;
}

void fit_camera_into(Camera& camera, const std::vector<glm::dvec3>& points, const Rect& view,
                     const Rect& free) {
    if (points.empty() || free.w < 8 || free.h < 8 || view.w < 8 || view.h < 8) return;
    const Camera before = camera;
    const Viewport vp{view.x, view.y, view.w, view.h};
    fit_to_points(camera, points, vp.aspect());
    // Fixed-point steps as in fit_to_points, toward the free rectangle's centre and ~90% of
    // its size (perspective is nearly linear over a view's width).
    const glm::dvec2 centre{free.x + free.w / 2.0, free.y + free.h / 2.0};
    for (int iter = 0; iter < 8; ++iter) {
        const glm::dmat4 m = view_projection(camera, vp.aspect());
        glm::dvec2 lo{1e300}, hi{-1e300};
        for (const glm::dvec3& p : points) {
            const Projected q = project(m, vp, p);
            if (!q.visible) {
                camera = before;
                return;
            }
            lo = glm::min(lo, q.pixel);
            hi = glm::max(hi, q.pixel);
        }
        const glm::dvec2 shift = (lo + hi) * 0.5 - centre;
        const double scale =
            std::max((hi.x - lo.x) / (0.9 * free.w), (hi.y - lo.y) / (0.9 * free.h));
        if (scale <= 0) break;
        // World units per pixel at the target's depth (camera.hpp: pan).
        const double unit = 2.0 * camera.distance * std::tan(camera.fov_y / 2) / view.h;
        camera.target += (shift.x * camera_right(camera) - shift.y * camera_up(camera)) * unit;
        camera.distance *= scale;
    }
}

CaptionFocus caption_focus(const doc::Document& d, const Camera& camera, const Rect& view,
                           float point_radius) {
    CaptionFocus f;
    const Viewport vp{view.x, view.y, std::max(view.w, 1.f), std::max(view.h, 1.f)};
    const glm::dmat4 m = view_projection(camera, vp.aspect());
    auto point_square = [&](const glm::dvec3& p) {
        const Projected q = project(m, vp, p);
        if (!q.visible) return;
        f.points.push_back({static_cast<float>(q.pixel.x) - point_radius,
                            static_cast<float>(q.pixel.y) - point_radius, 2 * point_radius,
                            2 * point_radius});
    };
    if (auto p = selected_point(d)) point_square(*p);
    // The indicator's point S(u, v), where the lesson shows it (or de Boor's construction).
    const doc::DisplaySettings& disp = d.view.display;
    const doc::Object* current = nullptr;
    if ((disp.indicator_point || disp.deboor) && current_surface(d, &current) && current) {
        const glm::dvec2 uv = indicator_params(d, *current);
        if (auto p = geom::surface_point(*current->surface(), uv.x, uv.y)) point_square(*p);
    }
    const doc::Object* sel = d.selected();
    for (const doc::Object& o : d.objects) {
        if (!o.visible || (sel && &o != sel)) continue;
        if (auto box = screen_box(outline_points(o, d.view.display), m, vp))
            f.objects.push_back(*box);
    }
    return f;
}

bool overlaps(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

float overlap_area(const Rect& a, const Rect& b) {
    const float w = std::min(a.x + a.w, b.x + b.w) - std::max(a.x, b.x);
    const float h = std::min(a.y + a.h, b.y + b.h) - std::max(a.y, b.y);
    return w > 0 && h > 0 ? w * h : 0.f;
}

Rect place_caption(const Rect& view, float w, float h, const CaptionFocus& focus, float margin,
                   const Rect* previous) {
    const float x0 = view.x + margin, y0 = view.y + margin;
    const float room_x = view.w - 2 * margin - w, room_y = view.h - 2 * margin - h;
    if (room_x < 0 || room_y < 0) return {view.x, view.y, w, h};
    // Candidates on a grid over the view: 9 columns by 9 rows of positions, edges included.
    constexpr int steps = 8;
    Rect best{};
    double best_score = std::numeric_limits<double>::infinity();
    const float top_centre_x = x0 + room_x / 2;
    for (int a = 0; a <= steps; ++a)
        for (int b = 0; b <= steps; ++b) {
            const Rect r{x0 + room_x * static_cast<float>(a) / steps,
                         y0 + room_y * static_cast<float>(b) / steps, w, h};
            double covered_points = 0, covered_objects = 0;
            for (const Rect& p : focus.points)
                covered_points += overlap_area(r, p) + (overlaps(r, p) ? 1 : 0);
            for (const Rect& o : focus.objects) covered_objects += overlap_area(r, o);
            // Points first by far, then the objects' area, then nearness to the top centre
            // (in pixels), then to where the box was.
            double score = covered_points * 1e12 + covered_objects * 1e3 +
                           std::hypot(r.x - top_centre_x, r.y - y0);
            if (previous) score += 0.01 * std::hypot(r.x - previous->x, r.y - previous->y);
            if (score < best_score) {
                best_score = score;
                best = r;
            }
        }
    return best;
}

} // namespace isoparm::ui
