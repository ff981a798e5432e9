// A curve's differential geometry as drawable pieces (DesignMentor's second curve system had
// the moving triad and the curvature circle): the curvature comb, the osculating circle and the
// Frenet frame at t, in 3D, for the curve designer's canvas and the 3D view alike. Every value
// comes from exact derivatives (geom::curve_curvature), never from the polyline.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "core/geom/types.hpp"

namespace isoparm::ui {

struct CurveGlyphs {
    // Teeth kappa(t) long along -N at samples in every knot span, scaled so the longest is a
    // fifth of the control polygon's size; `rim` joins their tips in order.
    std::vector<std::pair<glm::dvec3, glm::dvec3>> teeth; // base, tip
    std::vector<glm::dvec3> rim;
    // The circle of radius 1/kappa about C + N / kappa in the osculating plane (T, N).
    std::vector<glm::dvec3> circle;
    std::optional<glm::dvec3> centre;
    // The frame at C(t), each axis `frame_length` long.
    std::optional<glm::dvec3> point, tangent, normal, binormal;
    double frame_length = 0;
};

struct CurveGlyphRequest {
    bool comb = false, osculating = false, frenet = false;
};

// `t` in the curve's own parameters (inside its domain).
CurveGlyphs curve_glyphs(const geom::Curve& c, double t, const CurveGlyphRequest& want);

} // namespace isoparm::ui
