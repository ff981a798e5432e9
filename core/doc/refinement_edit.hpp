// Refinement-like shape edits (internal to core/doc): a new shape computed from the object's
// spline along one direction, with the selected control point following into the new net.
// Knot insertion and degree elevation (commands_refine.cpp) and the toolbox's removal,
// reduction, knot splitting and closing (commands_reshape.cpp) are all this.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"

namespace isoparm::doc::detail {

// The knot vector, degree and count of a shape along one direction (curves: their own).
struct Line {
    const geom::Knots* U = nullptr;
    int p = 0;
    int n = 0;
};
Line line_of(const Shape& shape, geom::Dir dir);

// The Greville abscissa of control point i, (U[i+1] + ... + U[i+p]) / p: the parameter a
// control point "belongs to" (Piegl & Tiller, sec. 9.3 and Farin). It is unchanged for the
// control points that knot insertion and splitting keep, so the nearest Greville abscissa
// finds "the same control point" in a new net.
double greville(const Line& L, int i);
int nearest_greville(const Line& L, double g);
int clamp_index(int i, int n);
// The selection's index along dir if it is a control point of object id, else null.
int* selected_index(Selection& sel, std::uint64_t id, bool curve, geom::Dir dir);
bool is_curve(const Shape& shape);
const char* dir_name(geom::Dir d);

// The object has knots (not an implicit or a triangle), and a curve is edited along its only
// direction.
geom::Status check_refinable(const Object& obj, geom::Dir dir, const char* what);
geom::Expected<Object*> refinable(Document& doc, std::uint64_t id, geom::Dir dir, const char* what);

// An index map takes the old line, the new line and the index in the line it maps from.
using IndexMap = std::function<int(const Line& old_line, const Line& new_line, int i)>;

struct Refinement {
    geom::Dir dir = geom::Dir::u;
    const char* what = "";
    std::function<geom::Expected<geom::Surface>(const geom::Surface&)> surface;
    std::function<geom::Expected<geom::Curve>(const geom::Curve&)> curve;
    // Triangular patches, where the edit has a meaning for them (degree elevation); without it
    // a triangle is refused (check_refinable).
    std::function<geom::Expected<geom::TrianglePatch>(const geom::TrianglePatch&)> triangle;
    // A curve's knot mode afterwards: custom (the refined knots are the curve's own) unless
    // the edit says otherwise (closing a curve makes it closed).
    CurveKnotMode curve_mode = CurveKnotMode::custom;
    // The history's label from the shapes before and after (a type change is appended).
    std::function<std::string(const Shape& before, const Shape& after)> label;
    // By default the control point with the nearest Greville abscissa.
    IndexMap forward = [](const Line& old_line, const Line& new_line, int i) {
        return nearest_greville(new_line, greville(old_line, i));
    };
    IndexMap backward = [](const Line& old_line, const Line& new_line, int i) {
        return nearest_greville(old_line, greville(new_line, i));
    };
};

// The shape edit (shape_edit.hpp) that replaces the object's shape by the refinement's.
std::unique_ptr<Command> refinement_command(std::uint64_t id, CommandSpec spec, Refinement r);

} // namespace isoparm::doc::detail
