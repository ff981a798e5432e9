// Trim loops in a surface's (u, v) domain: the outer boundary and the holes of a trimmed
// surface, each a closed chain of 2D NURBS curves, and the exact lines, arcs and polygons
// they are built from.
#pragma once

#include <glm/vec2.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/geom/status.hpp"
#include "core/geom/types.hpp"

namespace isoparm::geom {

// A closed chain of curves in the (u, v) plane: curve k ends where curve k + 1 starts, the last
// ends where the first starts. The curves are geom::Curve with z = 0 (x is u, y is v), so every
// curve algorithm serves them; lines are degree-1 B-splines and arcs rational quadratics
// (Piegl & Tiller A7.1), both exact.
struct TrimLoop {
    std::vector<Curve> curves;
};

// Which part of the domain a trimmed surface keeps: inside `outer` (counter-clockwise; absent:
// the whole domain rectangle) and outside every hole (each clockwise). The kept region lies to
// the left of every loop as it runs. No loop touches itself or another; holes lie inside the
// outer loop and apart from each other (core/geom/trim/trim_validate.hpp checks all of it).
struct Trim {
    std::optional<TrimLoop> outer;
    std::vector<TrimLoop> holes;

    bool empty() const { return !outer && holes.empty(); }
    int loop_count() const { return static_cast<int>(holes.size()) + (outer ? 1 : 0); }
    // Loop k in the order outer (when present), hole 0, hole 1, ...
    const TrimLoop& loop(int k) const;
    bool is_outer(int k) const { return outer && k == 0; }
};

// A surface and the trim that says which part of its domain it keeps (an exchange file's
// trimmed face).
struct TrimmedSurface {
    Surface surface;
    Trim trim;
};

// How messages name loop k of t: "the outer loop", "hole 2".
std::string loop_name(const Trim& t, int k);
// Its JSON Pointer below the trim: "/outer", "/holes/2".
std::string loop_path(const Trim& t, int k);

// The point a curve starts / ends at, in (u, v) (nullopt where its end does not exist, a zero
// denominator). Precondition: valid curve.
std::optional<glm::dvec2> curve_start(const Curve& c);
std::optional<glm::dvec2> curve_end(const Curve& c);
glm::dvec2 uv(const glm::dvec3& p);

// The segment a -> b: degree 1, two points, on [0, 1].
Curve trim_line(glm::dvec2 a, glm::dvec2 b);
// The circular arc about `centre` from `start_degrees` to `end_degrees` (counter-clockwise;
// end < start runs clockwise), exact (A7.1) on [0, 1]. Errors as circular_arc's, with the sweep
// at most 360 degrees either way ("/end").
Expected<Curve> trim_arc(glm::dvec2 centre, double radius, double start_degrees,
                         double end_degrees);

// Closed loops from their corners: the polygon through `corners` back to the first (at least
// three); the circle about `centre` (counter-clockwise, or clockwise for a hole); the domain
// rectangle, counter-clockwise from (u0, v0).
TrimLoop polygon_loop(const std::vector<glm::dvec2>& corners);
Expected<TrimLoop> circle_loop(glm::dvec2 centre, double radius, bool clockwise);
TrimLoop rectangle_loop(const ParamRect& r);
// The closed uniform cubic B-spline whose control polygon is `control` (at least three points,
// taken cyclically), as one cubic Bezier piece per point (Boehm's B-spline-to-Bezier points,
// exact): a smooth (C2) loop inside the polygon's convex hull, running the polygon's way.
TrimLoop smooth_loop(const std::vector<glm::dvec2>& control);

// The same curve run backwards: points and weights reversed, knots a + b - U[m - k].
Curve reversed(const Curve& c);
// The same loop run the other way round.
TrimLoop reversed(const TrimLoop& loop);

// Every curve and loop of t with (u, v) mapped by u' = a_u u + b_u, v' = a_v v + b_v (a > 0):
// how loops follow a surface whose knots were rescaled or shifted.
Trim map_affine(const Trim& t, glm::dvec2 scale, glm::dvec2 offset);

} // namespace isoparm::geom
