// Orbit camera maths: eye position, matrices, projection to pixels and picking rays.
#include "ui/view/camera.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <limits>

namespace isoparm::ui {

namespace {
constexpr double max_pitch = 1.5533; // 89 degrees: never look straight along z (up vector)
constexpr double radians_per_pixel = 0.008;

glm::dvec3 unit_offset(const Camera& c) {
    return {std::cos(c.pitch) * std::cos(c.yaw), std::cos(c.pitch) * std::sin(c.yaw),
            std::sin(c.pitch)};
}
} // namespace

glm::dvec3 camera_eye(const Camera& c) {
    return c.target + c.distance * unit_offset(c);
}
glm::dvec3 camera_forward(const Camera& c) {
    return -unit_offset(c);
}
glm::dvec3 camera_right(const Camera& c) {
    return glm::normalize(glm::cross(camera_forward(c), glm::dvec3(0, 0, 1)));
}
glm::dvec3 camera_up(const Camera& c) {
    return glm::cross(camera_right(c), camera_forward(c));
}

glm::dmat4 view_matrix(const Camera& c) {
    return glm::lookAt(camera_eye(c), c.target, glm::dvec3(0, 0, 1));
}

namespace {
// Clip planes follow the distance so zooming never clips the object being looked at.
double near_plane(const Camera& c) {
    return c.distance * 0.01;
}
} // namespace

glm::dmat4 projection_matrix(const Camera& c, double aspect) {
    return glm::perspective(c.fov_y, aspect, near_plane(c), c.distance * 100.0);
}

double near_plane_reach(const Camera& c, double aspect) {
    const double t = std::tan(c.fov_y / 2); // half height over distance
    return near_plane(c) * std::sqrt(1 + t * t * (1 + aspect * aspect));
}

glm::dmat4 view_projection(const Camera& c, double aspect) {
    return projection_matrix(c, aspect) * view_matrix(c);
}

void orbit(Camera& c, double dx_px, double dy_px) {
    c.yaw -= dx_px * radians_per_pixel;
    c.pitch = std::clamp(c.pitch + dy_px * radians_per_pixel, -max_pitch, max_pitch);
}

void pan(Camera& c, double dx_px, double dy_px, double viewport_height_px) {
    // World units per pixel at the target's depth, so the target follows the mouse.
    const double h = std::max(viewport_height_px, 1.0);
    const double scale = 2.0 * c.distance * std::tan(c.fov_y / 2) / h;
    c.target += (-dx_px * camera_right(c) + dy_px * camera_up(c)) * scale;
}

void zoom(Camera& c, double factor) {
    c.distance = std::clamp(c.distance * factor, 1e-4, 1e7);
}

void fit_to_points(Camera& c, const std::vector<glm::dvec3>& points, double aspect) {
    if (points.empty()) return;
    glm::dvec3 lo = points[0], hi = points[0];
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // A safe start: the bounding sphere inside the narrower field of view.
    c.target = (lo + hi) * 0.5;
    const double radius = std::max(glm::length(hi - lo) * 0.5, 1e-3);
    const double half_y = c.fov_y / 2;
    const double half_x = std::atan(std::tan(half_y) * aspect);
    c.distance = radius / std::sin(std::min(half_x, half_y)) * 1.05;
    const Camera safe = c;

    // The sphere is loose for flat shapes: re-centre the points' screen rectangle and scale
    // it to ~90% of the view, a few fixed-point steps (perspective is nearly linear here).
    const Viewport vp{-1, -1, 2, 2}; // "pixels" equal NDC (with y flipped)
    struct Extent {
        bool ok = true;
        glm::dvec2 lo{1e300}, hi{-1e300};
    };
    auto measure = [&]() {
        Extent e;
        const glm::dmat4 m = view_projection(c, aspect);
        for (const glm::dvec3& p : points) {
            const Projected pr = project(m, vp, p);
            if (!pr.visible) {
                e.ok = false;
                return e;
            }
            e.lo = glm::min(e.lo, pr.pixel);
            e.hi = glm::max(e.hi, pr.pixel);
        }
        return e;
    };
    for (int iter = 0; iter < 6; ++iter) {
        const Extent e = measure();
        if (!e.ok) break;
        const glm::dvec2 mid = (e.lo + e.hi) * 0.5;
        const double size = std::max(e.hi.x - e.lo.x, e.hi.y - e.lo.y) * 0.5;
        if (size <= 1e-9) break;
        // World size of one NDC unit at the target's depth.
        const double unit_y = std::tan(half_y) * c.distance;
        c.target += camera_right(c) * (mid.x * unit_y * aspect) - camera_up(c) * (mid.y * unit_y);
        c.distance *= size / 0.9;
    }
    const Extent e = measure();
    const bool inside =
        e.ok && e.lo.x >= -0.97 && e.lo.y >= -0.97 && e.hi.x <= 0.97 && e.hi.y <= 0.97;
    if (!inside) c = safe;
}

Projected project(const glm::dmat4& view_proj, const Viewport& vp, const glm::dvec3& p) {
    const glm::dvec4 clip = view_proj * glm::dvec4(p, 1.0);
    Projected out;
    if (clip.w <= 1e-12) return out;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    out.pixel = {vp.x + (ndc.x * 0.5 + 0.5) * vp.w, vp.y + (0.5 - ndc.y * 0.5) * vp.h};
    out.depth = ndc.z;
    out.visible = ndc.z >= -1.0 && ndc.z <= 1.0;
    return out;
}

Ray pixel_ray(const Camera& c, const Viewport& vp, const glm::dvec2& pixel) {
    const glm::dmat4 inv = glm::inverse(view_projection(c, vp.aspect()));
    const double nx = (pixel.x - vp.x) / vp.w * 2.0 - 1.0;
    const double ny = 1.0 - (pixel.y - vp.y) / vp.h * 2.0;
    glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0);
    glm::dvec4 b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
    return {pa, glm::normalize(pb - pa)};
}

std::optional<glm::dvec3> intersect_plane(const Ray& r, const glm::dvec3& point,
                                          const glm::dvec3& n) {
    const double denom = glm::dot(r.dir, n);
    if (std::abs(denom) < 1e-12) return std::nullopt;
    const double s = glm::dot(point - r.origin, n) / denom;
    if (s < 0) return std::nullopt;
    return r.origin + s * r.dir;
}

std::optional<glm::dvec3> closest_on_line(const Ray& r, const glm::dvec3& point,
                                          const glm::dvec3& dir) {
    // Minimise |point + s d - (o + t r)|: the standard two-line closest-points solve.
    const glm::dvec3 d = glm::normalize(dir);
    const glm::dvec3 w = point - r.origin;
    const double b = glm::dot(d, r.dir);
    const double denom = 1.0 - b * b;
    if (denom < 1e-9) return std::nullopt;
    const double s = (b * glm::dot(r.dir, w) - glm::dot(d, w)) / denom;
    return point + s * d;
}

glm::dvec3 drag_in_view_plane(const Camera& c, const Viewport& vp, const glm::dvec3& start,
                              const glm::dvec2& pixel) {
    const auto hit = intersect_plane(pixel_ray(c, vp, pixel), start, camera_forward(c));
    return hit ? *hit : start;
}

glm::dvec3 drag_along_axis(const Camera& c, const Viewport& vp, const glm::dvec3& start, int axis,
                           const glm::dvec2& pixel) {
    glm::dvec3 d(0.0);
    d[axis] = 1.0;
    const auto hit = closest_on_line(pixel_ray(c, vp, pixel), start, d);
    return hit ? *hit : start;
}

int dominant_axis(const Camera& c, const Viewport& vp, const glm::dvec3& p,
                  const glm::dvec2& screen_delta) {
    const glm::dmat4 vpm = view_projection(c, vp.aspect());
    const Projected o = project(vpm, vp, p);
    const double len = glm::length(screen_delta);
    int best = 0;
    double best_score = -1;
    for (int axis = 0; axis < 3; ++axis) {
        glm::dvec3 q = p;
        q[axis] += c.distance * 0.05;
        const Projected e = project(vpm, vp, q);
        const glm::dvec2 s = e.pixel - o.pixel;
        const double sl = glm::length(s);
        if (sl < 1e-9 || len < 1e-9) continue;
        const double score = std::abs(glm::dot(s, screen_delta)) / (sl * len);
        if (score > best_score) {
            best_score = score;
            best = axis;
        }
    }
    return best;
}

} // namespace isoparm::ui
