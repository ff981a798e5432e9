// Exact primitives for the curve designer: line segment, circular arc, full circle.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// The plane a primitive lies in, with its two axes (angles run from the first toward the
// second): xy = (x, y), xz = (x, z), yz = (y, z).
enum class Plane { xy, xz, yz };
inline constexpr EnumName<Plane> plane_names[] = {
    {Plane::xy, "xy"}, {Plane::xz, "xz"}, {Plane::yz, "yz"}};
static_assert(in_declaration_order(plane_names));
constexpr std::span<const EnumName<Plane>> enum_names(Plane) {
    return plane_names;
}
void plane_axes(Plane p, glm::dvec3& X, glm::dvec3& Y);

// The arc layout of Piegl & Tiller A7.1 / A8.1 for a sweep of `degrees` in (0, 360]: one
// rational quadratic segment per started 90 degrees, 2 * arcs + 1 points, knots
// 0^3 (1/arcs)^2 ... 1^3, and the middle weight cos(delta / 2) of each segment.
struct ArcLayout {
    int arcs = 1;
    double delta_degrees = 0; // per segment
    double middle_weight = 1; // cos(delta / 2)
    double middle_reach = 0;  // tan(delta / 2): the middle point is P + reach * (P turned 90)
    Knots knots;
};
ArcLayout arc_layout(double degrees);

// (cos, sin) of an angle in degrees, exact at multiples of 45 degrees (so quarter circles and
// their middle points have exact coordinates: (1, 0), (1, 1), (0, 1) for the unit circle).
glm::dvec2 cos_sin_degrees(double degrees);

// The segment P0 P1 as a rational quadratic (degree 2, three collinear points, unit weights,
// uniform speed) on [0, 1], so it mixes with arcs without degree elevation.
Curve line_segment(const glm::dvec3& P0, const glm::dvec3& P1);

// Piegl & Tiller A7.1 MakeNurbsCircle: the arc of the circle centre + r (cos a X + sin a Y)
// from a = start to a = end (degrees), exact, on [0, 1]. Errors (`schema`): radius <= 0 or not
// finite ("/radius"), end <= start or end - start > 360 ("/end"), non-finite angles.
Expected<Curve> circular_arc(const glm::dvec3& centre, double radius, double start_degrees,
                             double end_degrees, Plane plane);
Expected<Curve> circular_arc(const glm::dvec3& centre, double radius, double start_degrees,
                             double end_degrees, const glm::dvec3& X, const glm::dvec3& Y);

// The full circle (nine points, four quarter arcs), starting at centre + r X.
Expected<Curve> full_circle(const glm::dvec3& centre, double radius, Plane plane);

} // namespace isoparm::geom
