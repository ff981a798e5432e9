// The Homogeneous view's picture, without a window: a planar rational curve (or a surface's
// isocurve seen in a coordinate plane) lifted to (w a, w b, w), where it is a polynomial curve
// with the control points (w_i a_i, w_i b_i, w_i); its central projection from the origin onto
// the plane w = 1 is the rational curve. The panel draws this through an orbiting camera.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/geom/types.hpp"

namespace isoparm::ui {

struct HomogeneousScene {
    std::vector<glm::dvec3> lifted_points;    // (w a, w b, w) per control point
    std::vector<glm::dvec3> projected_points; // (a, b, 1): where each ray meets w = 1
    std::vector<double> weights;
    std::vector<glm::dvec3> lifted_curve;                  // C^w(t) samples
    std::vector<std::vector<glm::dvec3>> projected_curve;  // C(t) on w = 1, broken at w = 0
    std::optional<glm::dvec3> lifted_at_t, projected_at_t; // at the traced parameter
    double t = 0;
    glm::dvec2 plane_lo{0}, plane_hi{0}; // the part of w = 1 drawn (a, b), around the picture
    glm::dvec3 lo{0}, hi{0};             // everything drawn, the origin included
};

// `axes`: the two coordinates seen (0 x, 1 y, 2 z); `t` in the curve's own parameters.
HomogeneousScene homogeneous_scene(const geom::Curve& c, std::array<int, 2> axes, double t,
                                   int samples = 200);

// The two coordinates a curve is best seen in: the pair with the largest extents of its
// control points (a surface's isocurve across a hill is seen from the side, not from above).
std::array<int, 2> best_plane(const geom::Curve& c);

// An orthographic orbit camera for the picture: yaw about the w axis, then pitch; the result
// is (right, up, depth) in the picture's units before scaling.
glm::dvec3 orbit_project(const glm::dvec3& p, double yaw_degrees, double pitch_degrees);

} // namespace isoparm::ui
