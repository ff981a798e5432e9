// Helpers shared by the command implementations (internal to core/doc).
#pragma once

#include <cstdint>
#include <string>

#include "core/doc/document.hpp"
#include "core/doc/kinds/kind_common.hpp"
#include "core/geom/status.hpp"

namespace isoparm::doc::detail {

// The object with this id, or a `schema` error at "/id".
geom::Expected<Object*> find_object(Document& doc, std::uint64_t id);
geom::Expected<const Object*> find_object(const Document& doc, std::uint64_t id);

// Full validation of a shape the document will hold: geometry (degree, knots, weights, the
// type's rules, the size caps) or, for implicits, the box, the cell and the parameters.
// Paths are relative to the shape's geometry ("/knots/0/3").
geom::Status validate_shape(const Shape& shape);

// Object names: non-empty, no control characters (`schema` at "/name"). No length cap:
// repeated splits grow names ("hill.1.2.1"), and a scene must load what it saved.
geom::Status validate_name(const std::string& name);

// Approximate heap bytes of a shape, for the history's memory bound.
std::size_t shape_bytes(const Shape& shape);

} // namespace isoparm::doc::detail
