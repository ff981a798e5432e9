// The one command that replaces an object's shape (internal to core/doc): edit_shape, the curve
// designer's edits and refinement (knot insertion, degree elevation) are all this command with
// a different rule for the new shape and for where a selected control point goes.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/doc/command.hpp"
#include "core/doc/command_spec.hpp"

namespace isoparm::doc::detail {

struct ShapeEditRule {
    // The new shape, from the object as it is now; a refusal names its value. The result must
    // be the same kind of object and pass validate_shape (errors under `shape_path`).
    std::function<geom::Expected<Shape>(const Object&)> make;
    // The history's label, from the shapes before and after.
    std::function<std::string(const Shape& before, const Shape& after)> label;
    // Where the selection goes in the new shape (`forward`) and, on undo when the user has
    // selected something since, back (`backward`). Either may be empty: the selection stays.
    // A control point index the shape does not have is dropped afterwards.
    std::function<Selection(const Selection&, const Shape&from, const Shape&to)> forward, backward;
    // Consecutive edits of one object with the same non-empty key merge (a drag).
    std::string merge_key;
    std::string shape_path = "/shape";
};

std::unique_ptr<Command> shape_edit(std::uint64_t id, CommandSpec spec, ShapeEditRule rule);

// "rational Bezier becomes NURBS" when the spline type differs between the shapes, else "".
std::string type_change_text(const Shape& before, const Shape& after);
// The type change of an applied shape edit ("" for any other command).
std::string shape_edit_type_change(const Command& command);

} // namespace isoparm::doc::detail
