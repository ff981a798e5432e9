// The selection of many points, box selection, and the handle's layout, hits and maps.
#include "ui/view/point_selection.hpp"
#include "ui/view/kinds/kind_view.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace isoparm::ui {

bool PointSelection::contains(PointIndex p) const {
    return std::binary_search(points.begin(), points.end(), p);
}

void PointSelection::toggle(PointIndex p) {
    const auto it = std::lower_bound(points.begin(), points.end(), p);
    if (it != points.end() && *it == p)
        points.erase(it);
    else
        points.insert(it, p);
}

void PointSelection::add(const std::vector<PointIndex>& more) {
    points.insert(points.end(), more.begin(), more.end());
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
}

void PointSelection::set(std::uint64_t id, std::vector<PointIndex> p) {
    object = id;
    points = std::move(p);
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
}

void sync_selection(PointSelection& s, const doc::Document& doc) {
    const doc::Selection& sel = doc.view.selection;
    const doc::Object* o = doc.find(sel.object);
    if (!o || !sel.has_point()) {
        s = PointSelection{};
        if (o) s.object = o->id;
        return;
    }
    const PointIndex primary{sel.i, two_index_points(o->shape) ? sel.j : -1};
    if (s.object != o->id) s = PointSelection{o->id, {}};
    std::erase_if(s.points,
                  [&](PointIndex p) { return !doc::has_control_point(o->shape, p.i, p.j); });
    if (!s.contains(primary)) s.add({primary});
}

std::optional<PointIndex> primary_after_toggle(const PointSelection& s, PointIndex p,
                                               PointIndex primary) {
    if (s.contains(p)) return p;
    if (s.points.empty()) return std::nullopt;
    if (s.contains(primary)) return primary;
    return s.points.front();
}

std::vector<std::size_t> inside_box(const std::vector<glm::dvec2>& pixels, const glm::dvec2& a,
                                    const glm::dvec2& b) {
    const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < pixels.size(); ++k)
        if (pixels[k].x >= lo.x && pixels[k].x <= hi.x && pixels[k].y >= lo.y &&
            pixels[k].y <= hi.y)
            out.push_back(k);
    return out;
}

namespace {

constexpr int ring_segments = 48;

// The ring about `axis` through the pivot, with world radius r, projected.
std::vector<glm::dvec2> projected_ring(const glm::dmat4& m, const Viewport& vp,
                                       const glm::dvec3& pivot, int axis, double r) {
    std::vector<glm::dvec2> out;
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    for (int k = 0; k < ring_segments; ++k) {
        const double t = 2 * std::acos(-1.0) * k / ring_segments;
        glm::dvec3 p = pivot;
        p[a] += r * std::cos(t);
        p[b] += r * std::sin(t);
        const Projected q = project(m, vp, p);
        if (!q.visible) return {};
        out.push_back(q.pixel);
    }
    return out;
}

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 d = b - a;
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0 ? std::clamp(glm::dot(p - a, d) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * d));
}

} // namespace

HandleLayout handle_layout_3d(const Camera& c, const Viewport& vp, const glm::dvec3& pivot,
                              double size_px) {
    HandleLayout h;
    const glm::dmat4 m = view_projection(c, vp.aspect());
    const Projected centre = project(m, vp, pivot);
    h.centre = centre.pixel;
    if (!centre.visible) return h;
    // World length of size_px at the pivot's depth.
    const glm::dvec3 eye = camera_eye(c);
    const double depth = std::max(glm::dot(pivot - eye, camera_forward(c)), 1e-9);
    const double world = size_px * 2 * depth * std::tan(c.fov_y / 2) / std::max(vp.h, 1.0);
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 end = pivot;
        end[a] += world;
        const Projected tip = project(m, vp, end);
        // An axis seen nearly end-on has no arrow to grab.
        if (tip.visible && glm::length(tip.pixel - h.centre) > 0.25 * size_px) {
            h.axis_shown[a] = true;
            h.tip[a] = tip.pixel;
        }
        h.ring[a] = projected_ring(m, vp, pivot, a, 0.75 * world);
        // Seen edge-on, a ring is a line: no angle can be read from it.
        if (!h.ring[a].empty()) {
            glm::dvec2 lo = h.ring[a][0], hi = lo;
            for (const glm::dvec2& p : h.ring[a]) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
            if (std::min(hi.x - lo.x, hi.y - lo.y) < 0.2 * size_px) h.ring[a].clear();
        }
    }
    h.scale_box = h.centre + glm::dvec2(0.55, -0.55) * size_px;
    return h;
}

HandleLayout handle_layout_plane(const PlaneMap& m, int a, int b, const glm::dvec3& pivot,
                                 double size_px) {
    HandleLayout h;
    h.centre = plane_to_pixel(m, {pivot[a], pivot[b]});
    h.axis_shown[a] = h.axis_shown[b] = true;
    h.tip[a] = h.centre + glm::dvec2(size_px, 0);
    h.tip[b] = h.centre + glm::dvec2(0, -size_px);
    const int normal = 3 - a - b;
    for (int k = 0; k < ring_segments; ++k) {
        const double t = 2 * std::acos(-1.0) * k / ring_segments;
        h.ring[normal].push_back(h.centre + 0.75 * size_px * glm::dvec2(std::cos(t), std::sin(t)));
    }
    h.scale_box = h.centre + glm::dvec2(0.55, -0.55) * size_px;
    return h;
}

HandlePart hit_handle(const HandleLayout& h, const glm::dvec2& mouse, double radius) {
    if (glm::length(mouse - h.centre) <= std::max(h.centre_radius, radius))
        return HandlePart::centre;
    if (std::abs(mouse.x - h.scale_box.x) <= h.box_half + radius * 0.5 &&
        std::abs(mouse.y - h.scale_box.y) <= h.box_half + radius * 0.5)
        return HandlePart::scale;
    const HandlePart arrows[3] = {HandlePart::arrow_x, HandlePart::arrow_y, HandlePart::arrow_z};
    const HandlePart rings[3] = {HandlePart::ring_x, HandlePart::ring_y, HandlePart::ring_z};
    HandlePart best = HandlePart::none;
    double best_d = radius;
    for (int a = 0; a < 3; ++a) {
        if (!h.axis_shown[a]) continue;
        // The arrow's outer part (near the centre it is the centre's).
        const glm::dvec2 from = h.centre + 0.35 * (h.tip[a] - h.centre);
        const double d = distance_to_segment(mouse, from, h.tip[a]);
        if (d <= best_d) {
            best_d = d;
            best = arrows[a];
        }
    }
    if (best != HandlePart::none) return best;
    for (int a = 0; a < 3; ++a) {
        const auto& r = h.ring[a];
        for (std::size_t k = 0; k < r.size(); ++k) {
            const double d = distance_to_segment(mouse, r[k], r[(k + 1) % r.size()]);
            if (d <= best_d) {
                best_d = d;
                best = rings[a];
            }
        }
    }
    return best;
}

int handle_axis(HandlePart p) {
    switch (p) {
    case HandlePart::arrow_x:
    case HandlePart::ring_x:
        return 0;
    case HandlePart::arrow_y:
    case HandlePart::ring_y:
        return 1;
    case HandlePart::arrow_z:
    case HandlePart::ring_z:
        return 2;
    default:
        return -1;
    }
}

glm::dmat4 ring_turn(int axis, const glm::dvec3& pivot, const glm::dvec2& pivot_px,
                     const glm::dvec2& press, const glm::dvec2& now, bool axis_toward_viewer,
                     double snap_degrees) {
    const glm::dvec2 a = press - pivot_px, b = now - pivot_px;
    if (glm::length(a) < 1 || glm::length(b) < 1) return glm::dmat4(1.0);
    // Screen y points down: counter-clockwise on screen is a negative angle in pixel axes.
    double degrees = -(std::atan2(b.y, b.x) - std::atan2(a.y, a.x)) * 180 / std::acos(-1.0);
    while (degrees > 180) degrees -= 360;
    while (degrees < -180) degrees += 360;
    if (!axis_toward_viewer) degrees = -degrees;
    if (snap_degrees > 0) degrees = std::round(degrees / snap_degrees) * snap_degrees;
    return doc::about(doc::rotation(axis, degrees), pivot);
}

glm::dmat4 box_scale(const glm::dvec3& pivot, const glm::dvec2& pivot_px, const glm::dvec2& press,
                     const glm::dvec2& now, double snap_step) {
    const double d0 = glm::length(press - pivot_px), d1 = glm::length(now - pivot_px);
    if (d0 < 1) return glm::dmat4(1.0);
    double f = d1 / d0;
    if (snap_step > 0) f = std::max(snap_step, std::round(f / snap_step) * snap_step);
    return doc::about(doc::scaling(glm::dvec3(f)), pivot);
}

} // namespace isoparm::ui
