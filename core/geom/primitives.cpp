// Lines, arcs and circles as exact rational quadratics (Piegl & Tiller A7.1).
#include "core/geom/primitives.hpp"

#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>

namespace isoparm::geom {

void plane_axes(Plane p, glm::dvec3& X, glm::dvec3& Y) {
    switch (p) {
    case Plane::xy:
        X = {1, 0, 0}, Y = {0, 1, 0};
        return;
    case Plane::xz:
        X = {1, 0, 0}, Y = {0, 0, 1};
        return;
    case Plane::yz:
        X = {0, 1, 0}, Y = {0, 0, 1};
        return;
    }
}

glm::dvec2 cos_sin_degrees(double degrees) {
    double r = std::fmod(degrees, 360.0);
    if (r < 0.0) r += 360.0;
    const double h = std::sqrt(0.5);
    if (r == 0.0) return {1.0, 0.0};
    if (r == 45.0) return {h, h};
    if (r == 90.0) return {0.0, 1.0};
    if (r == 135.0) return {-h, h};
    if (r == 180.0) return {-1.0, 0.0};
    if (r == 225.0) return {-h, -h};
    if (r == 270.0) return {0.0, -1.0};
    if (r == 315.0) return {h, -h};
    const double a = r * std::numbers::pi / 180.0;
    return {std::cos(a), std::sin(a)};
}

ArcLayout arc_layout(double degrees) {
    assert(degrees > 0.0 && degrees <= 360.0);
    ArcLayout a;
    a.arcs = degrees <= 90.0 ? 1 : degrees <= 180.0 ? 2 : degrees <= 270.0 ? 3 : 4;
    a.delta_degrees = degrees / a.arcs;
    const glm::dvec2 half = cos_sin_degrees(a.delta_degrees / 2.0);
    a.middle_weight = half.x;
    a.middle_reach = half.y / half.x;
    const int n = 2 * a.arcs + 1;
    a.knots.assign(static_cast<size_t>(n) + 3, 0.0);
    for (int k = 0; k < 3; ++k) a.knots[n + k] = 1.0;
    // Interior knots at 1/arcs, 2/arcs, ... each twice (A7.1): C1 joins of the quadratic arcs.
    for (int s = 1; s < a.arcs; ++s) {
        const double t = static_cast<double>(s) / a.arcs;
        a.knots[1 + 2 * s] = a.knots[2 + 2 * s] = t;
    }
    return a;
}

Curve line_segment(const glm::dvec3& P0, const glm::dvec3& P1) {
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 2;
    c.knots = {0, 0, 0, 1, 1, 1};
    c.points = {P0, 0.5 * (P0 + P1), P1};
    c.weights = {1, 1, 1};
    return c;
}

Expected<Curve> circular_arc(const glm::dvec3& centre, double radius, double start_degrees,
                             double end_degrees, const glm::dvec3& X, const glm::dvec3& Y) {
    if (!std::isfinite(radius) || radius <= 0.0)
        return make_error(ErrorCode::schema,
                          "the radius must be a positive number, got " + format_number(radius),
                          "/radius");
    if (!std::isfinite(start_degrees))
        return make_error(ErrorCode::schema, "the start angle must be a finite number", "/start");
    if (!std::isfinite(end_degrees))
        return make_error(ErrorCode::schema, "the end angle must be a finite number", "/end");
    const double sweep = end_degrees - start_degrees;
    if (!(sweep > 0.0 && sweep <= 360.0)) {
        return make_error(ErrorCode::schema,
                          "the end angle must exceed the start angle by at most 360 degrees, got " +
                              format_number(start_degrees) + " to " + format_number(end_degrees),
                          "/end");
    }
    const ArcLayout a = arc_layout(sweep);
    Curve c;
    c.type = SplineType::nurbs;
    c.degree = 2;
    c.knots = a.knots;
    // End points on the circle with weight 1; each middle point where the end tangents meet
    // (the start point plus tan(delta / 2) times the radius turned by 90 degrees), with weight
    // cos(delta / 2) (A7.1).
    for (int s = 0; s <= a.arcs; ++s) {
        const glm::dvec2 cs = cos_sin_degrees(start_degrees + s * a.delta_degrees);
        const glm::dvec3 radial = radius * (cs.x * X + cs.y * Y);
        c.points.push_back(centre + radial);
        c.weights.push_back(1.0);
        if (s == a.arcs) break;
        const glm::dvec3 turned = radius * (-cs.y * X + cs.x * Y);
        c.points.push_back(centre + radial + a.middle_reach * turned);
        c.weights.push_back(a.middle_weight);
    }
    // A full circle closes exactly: the last point is the first, not a rounded copy of it.
    if (sweep == 360.0) c.points.back() = c.points.front();
    return c;
}

Expected<Curve> circular_arc(const glm::dvec3& centre, double radius, double start_degrees,
                             double end_degrees, Plane plane) {
    glm::dvec3 X, Y;
    plane_axes(plane, X, Y);
    return circular_arc(centre, radius, start_degrees, end_degrees, X, Y);
}

Expected<Curve> full_circle(const glm::dvec3& centre, double radius, Plane plane) {
    return circular_arc(centre, radius, 0.0, 360.0, plane);
}

} // namespace isoparm::geom
