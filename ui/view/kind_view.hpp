// The workstation's questions about an object's kind, each answered by one std::visit over
// doc::Shape that lists every kind (kind_view.cpp): a new kind stops the build there, and the
// panels that ask through these functions follow it.
#pragma once

#include <memory>

#include "core/doc/command.hpp"
#include "core/doc/document.hpp"

namespace isoparm::ui {

// Which editor takes the right column's top slot while an object of the kind is selected.
enum class ObjectEditor { control_points, curve_designer, implicit_surface };
ObjectEditor editor_of(const doc::Object& o);

// Whether a control point of the shape is named by two indices (a surface's (i, j), a
// triangle's (i, j) of b_ijk) or by one (a curve's i, j = -1); a kind without control points
// names none (false).
bool two_index_points(const doc::Shape& shape);

// The command that moves control point (i, j) of o to p (a curve: point i).
std::unique_ptr<doc::Command> move_point_command(const doc::Object& o, int i, int j,
                                                 const glm::dvec3& p);

// The Objects tab's Kind column: a surface by its spline type, else the kind as scene files
// name it.
const char* kind_label(const doc::Object& o);

} // namespace isoparm::ui
