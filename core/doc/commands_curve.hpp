// The curve designer's document commands: points, degree, knot mode, plane, primitives.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/doc/command.hpp"

namespace isoparm::doc {

// The knot rule of a curve (docs/constructions.md, "The curve designer"). Inserting or deleting
// a control point or setting the degree recomputes the knots from the curve's knot mode, on
// [0, 1]: clamped uniform, or averaged (Piegl & Tiller eq. 9.8) from the chord-length /
// centripetal parameters of the new control polygon. Custom knots are the user's own: these
// three commands refuse them (`knots`, path "/knot_mode", the message says what to do), since
// no rule says where a new knot belongs; knot insertion and degree elevation (which keep the
// shape) and set_knot work in every mode. Bezier types keep their rule instead: the degree is
// the point count - 1, so inserting or deleting a point changes the degree with it.

// "clamped uniform", "chord length", "centripetal", "custom" (menus, labels, messages).
const char* knot_mode_label(CurveKnotMode mode);
// "xy", "xz", "yz", "3D".
const char* curve_plane_label(CurvePlane plane);

// The knots the mode gives for this curve's points and degree (custom: the curve's own).
// Errors as geom::knots_for_points: `geometry` for a degenerate control polygon under
// chord / centripetal (two consecutive points equal, or all points equal).
geom::Expected<geom::Knots> knots_for_mode(const geom::Curve& curve, CurveKnotMode mode);

// A new curve object for add_object: the given points, degree and knot mode (custom is
// refused here: a new curve has no user knots yet), unit weights, type bspline (nurbs when
// `rational`). Errors: fewer than 2 points (`schema`, "/points"), degree outside
// 1..count - 1 (`degree`, "/degree"), a degenerate polygon under chord / centripetal.
geom::Expected<Object> new_curve_object(std::string name, CurvePlane plane,
                                        std::vector<glm::dvec3> points, int degree,
                                        CurveKnotMode mode, bool rational = false);
// The exact primitives of core/geom/primitives.hpp as objects (rational quadratics, knot mode
// custom: their knots carry the arcs). The plane must be xy, xz or yz for arcs and circles
// (`schema`, "/plane"); geometry errors pass through ("/radius", "/end").
geom::Expected<Object> line_object(std::string name, CurvePlane plane, const glm::dvec3& p0,
                                   const glm::dvec3& p1);
geom::Expected<Object> arc_object(std::string name, CurvePlane plane, const glm::dvec3& centre,
                                  double radius, double start_degrees, double end_degrees);
geom::Expected<Object> circle_object(std::string name, CurvePlane plane, const glm::dvec3& centre,
                                     double radius);

// Commands on curve objects (any other kind is `schema` at "/id"). All are undoable, restore
// the curve bit for bit, and refuse without changing anything; refusals name the value.

// Inserts a control point before index i (i = count appends), weight 1; the new point becomes
// the selection. Errors: i outside 0..count (`schema`, "/i"), non-finite position ("/position/k"),
// custom knots, a chord / centripetal polygon the new point makes degenerate (`geometry`,
// "/position"), more than 4096 points (`limit`, "/i").
std::unique_ptr<Command> insert_curve_point(std::uint64_t id, int i, glm::dvec3 position);
// Deletes control point i. The selection, if on this curve, keeps its point (or the nearest
// one left). Errors: i out of range (`schema`, "/i"); too few points left for the degree
// (`degree`, "/i": a degree-p curve needs p + 1 points; a curve needs 2), custom knots,
// a degenerate polygon under chord / centripetal (`geometry`, "/i").
std::unique_ptr<Command> delete_curve_point(std::uint64_t id, int i);
// Moves control point i; under chord / centripetal knots the knots follow the polygon
// (otherwise this is move_control_point). Consecutive moves of the same point merge (a drag
// is one undo step). Errors as move_control_point, plus a degenerate polygon (`geometry`,
// "/position").
std::unique_ptr<Command> move_curve_point(std::uint64_t id, int i, glm::dvec3 position);
// Sets the degree (the shape changes; elevate_degree keeps it). Errors: degree outside
// 1..count - 1 (`degree`, "/degree"), a Bezier type (its degree is count - 1: `degree`,
// "/degree"), custom knots.
std::unique_ptr<Command> set_curve_degree(std::uint64_t id, int degree);
// Sets the knot mode; every mode but custom recomputes the knots now (custom keeps them).
std::unique_ptr<Command> set_curve_knot_mode(std::uint64_t id, CurveKnotMode mode);
// Sets the plane the designer edits the curve in. With carry_points, and both planes xy / xz /
// yz, every point's coordinates along the old plane's first axis, second axis and normal
// become those along the new plane's (xy: x, y, z; xz: x, z, y; yz: y, z, x): the drawing
// moves into the new plane unchanged. Otherwise (or with free 3D) the points stay.
std::unique_ptr<Command> set_curve_plane(std::uint64_t id, CurvePlane plane, bool carry_points);
// Makes the curves compatible (geom::make_compatible: one degree and one knot vector on
// [0, 1], shapes unchanged) in one undo step; their knot mode becomes custom. Errors name the
// curve: fewer than 2 ids (`schema`, "/ids"), an id that is no curve (`schema`, "/ids/k"),
// the same curve twice (`schema`, "/ids/k"), geometry errors with "/ids/k" for "/curves/k".
std::unique_ptr<Command> make_curves_compatible(std::vector<std::uint64_t> ids);

} // namespace isoparm::doc
