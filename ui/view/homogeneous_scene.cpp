// The Homogeneous view's picture (see the header): geom::homogeneous_lift and the curve itself.
#include "ui/view/homogeneous_scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/rational_picture.hpp"
#include "core/geom/tessellate.hpp"

namespace isoparm::ui {

HomogeneousScene homogeneous_scene(const geom::Curve& c, std::array<int, 2> axes, double t,
                                   int samples) {
    HomogeneousScene h;
    h.t = t;
    const geom::Curve lifted = geom::homogeneous_lift(c, axes);
    h.lifted_points = lifted.points;
    for (std::size_t k = 0; k < c.points.size(); ++k) {
        h.weights.push_back(lifted.points[k].z);
        h.projected_points.emplace_back(c.points[k][axes[0]], c.points[k][axes[1]], 1.0);
    }
    const geom::Interval d = geom::domain(c);
    std::vector<glm::dvec3> piece;
    double last_w = 0;
    for (double s : geom::uniform_params(d.lo, d.hi, std::max(samples, 2))) {
        const auto q = geom::curve_point(lifted, s); // a polynomial curve: always exists
        if (!q) continue;
        h.lifted_curve.push_back(*q);
        // Where w changes sign the curve passes through infinity: the line breaks there
        // instead of joining its two far ends across the picture.
        if ((q->z == 0 || last_w * q->z < 0) && !piece.empty()) {
            h.projected_curve.push_back(std::move(piece));
            piece.clear();
        }
        last_w = q->z;
        if (const auto p = geom::curve_point(c, s))
            piece.emplace_back((*p)[axes[0]], (*p)[axes[1]], 1.0);
    }
    if (!piece.empty()) h.projected_curve.push_back(std::move(piece));
    h.lifted_at_t = geom::curve_point(lifted, t);
    if (const auto p = geom::curve_point(c, t))
        h.projected_at_t = glm::dvec3((*p)[axes[0]], (*p)[axes[1]], 1.0);

    // The plane w = 1 drawn around the projected control points, and the curve where it stays
    // near them: where w nears 0 the curve runs off to infinity, and framing those far points
    // would shrink the rest to nothing (the picture clips them instead).
    glm::dvec2 lo{0}, hi{0};
    for (std::size_t k = 0; k < h.projected_points.size(); ++k) {
        const glm::dvec2 p(h.projected_points[k]);
        lo = k == 0 ? p : glm::min(lo, p);
        hi = k == 0 ? p : glm::max(hi, p);
    }
    const glm::dvec2 reach = 0.5 * glm::dvec2(std::max({hi.x - lo.x, hi.y - lo.y, 1e-9}));
    const glm::dvec2 near_lo = lo - reach, near_hi = hi + reach;
    for (const auto& run : h.projected_curve)
        for (const glm::dvec3& q : run) {
            const glm::dvec2 p(q);
            if (glm::all(glm::greaterThanEqual(p, near_lo)) &&
                glm::all(glm::lessThanEqual(p, near_hi))) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            }
        }
    // A curve seen edge-on (a straight line in this plane) still gets a plane one can see.
    const double side = std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
    const glm::dvec2 centre = 0.5 * (lo + hi);
    const glm::dvec2 half = 0.5 * glm::max(hi - lo, glm::dvec2(0.4 * side)) + 0.1 * side;
    h.plane_lo = centre - half;
    h.plane_hi = centre + half;
    h.lo = glm::dvec3(std::min(h.plane_lo.x, 0.0), std::min(h.plane_lo.y, 0.0), 0.0);
    h.hi = glm::dvec3(std::max(h.plane_hi.x, 0.0), std::max(h.plane_hi.y, 0.0), 1.0);
    for (const glm::dvec3& p : h.lifted_points) {
        h.lo = glm::min(h.lo, p);
        h.hi = glm::max(h.hi, p);
    }
    return h;
}

std::array<int, 2> best_plane(const geom::Curve& c) {
    glm::dvec3 lo(0.0), hi(0.0);
    for (std::size_t k = 0; k < c.points.size(); ++k) {
        lo = k == 0 ? c.points[k] : glm::min(lo, c.points[k]);
        hi = k == 0 ? c.points[k] : glm::max(hi, c.points[k]);
    }
    const glm::dvec3 e = hi - lo;
    // Leave out the axis of the smallest extent (ties keep x before y before z).
    if (e.z < e.x && e.z < e.y) return {0, 1};
    if (e.y < e.x) return {0, 2};
    if (e.x < e.y || e.x < e.z) return {1, 2};
    return {0, 1};
}

glm::dvec3 orbit_project(const glm::dvec3& p, double yaw_degrees, double pitch_degrees) {
    const double y = yaw_degrees * 3.14159265358979323846 / 180;
    const double q = pitch_degrees * 3.14159265358979323846 / 180;
    // w is up; yaw turns the (a, b) plane about it, pitch tilts the picture toward the viewer.
    const double right = p.x * std::cos(y) - p.y * std::sin(y);
    const double depth = p.x * std::sin(y) + p.y * std::cos(y);
    const double up = p.z * std::cos(q) + depth * std::sin(q);
    return {right, up, depth * std::cos(q) - p.z * std::sin(q)};
}

} // namespace isoparm::ui
