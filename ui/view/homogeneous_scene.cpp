// The Homogeneous view's picture (see the header): geom::homogeneous_lift and the curve itself.
#include "ui/view/homogeneous_scene.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

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

    // The plane w = 1 drawn around the projected control points and curve (points far away
    // where w is nearly 0 would shrink the rest to nothing: those are left to the rays).
    glm::dvec2 lo{-1, -1}, hi{1, 1};
    bool any = false;
    auto take = [&](const glm::dvec3& p) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
        lo = any ? glm::min(lo, glm::dvec2(p)) : glm::dvec2(p);
        hi = any ? glm::max(hi, glm::dvec2(p)) : glm::dvec2(p);
        any = true;
    };
    for (const auto& run : h.projected_curve)
        for (const glm::dvec3& p : run) take(p);
    for (const glm::dvec3& p : h.projected_points) take(p);
    const glm::dvec2 margin = 0.1 * glm::max(hi - lo, glm::dvec2(1e-9));
    h.plane_lo = lo - margin;
    h.plane_hi = hi + margin;
    h.lo = glm::dvec3(std::min(h.plane_lo.x, 0.0), std::min(h.plane_lo.y, 0.0), 0.0);
    h.hi = glm::dvec3(std::max(h.plane_hi.x, 0.0), std::max(h.plane_hi.y, 0.0), 1.0);
    for (const glm::dvec3& p : h.lifted_points) {
        h.lo = glm::min(h.lo, p);
        h.hi = glm::max(h.hi, p);
    }
    return h;
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
