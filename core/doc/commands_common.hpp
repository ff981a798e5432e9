// Helpers shared by the command implementations (internal to core/doc).
#pragma once

#include <cstdint>
#include <string>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::doc::detail {

// The object with this id, or a `schema` error at "/id".
geom::Expected<Object*> find_object(Document& doc, std::uint64_t id);
geom::Expected<const Object*> find_object(const Document& doc, std::uint64_t id);

// "surface", "curve", "implicit surface", "triangular patch": for messages.
const char* kind_name(const Shape& shape);

// Full validation of a shape the document will hold: geometry (degree, knots, weights, the
// type's rules, the size caps) or, for implicits, the box, the cell and the parameters.
// Paths are relative to the shape's geometry ("/knots/0/3").
geom::Status validate_shape(const Shape& shape);

// Object names: non-empty, no control characters (`schema` at "/name"). No length cap:
// repeated splits grow names ("hill.1.2.1"), and a scene must load what it saved.
geom::Status validate_name(const std::string& name);

// The size caps for a surface / curve that an edit produced (`limit` at `path`).
geom::Status check_size(const Shape& shape, const std::string& path);

// Labels: "P23" (surface, both indices < 10), "P12,3" (otherwise), "P4" (curve, j < 0).
std::string point_label(char letter, int i, int j);
// Triangles: "b210" (every index < 10), "b12,3,0" otherwise; k = n - i - j.
std::string triangle_point_label(char letter, int n, int i, int j);

// Approximate heap bytes of a shape, for the history's memory bound.
std::size_t shape_bytes(const Shape& shape);

} // namespace isoparm::doc::detail
