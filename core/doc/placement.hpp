// Where a new object goes: beside what the scene already holds, never on top of it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "core/doc/document.hpp"

namespace isoparm::doc {

// The box of an object's control points (an implicit surface: its polygonization bounds).
std::optional<Box> bounds_of(const Shape& shape);
// The box of every visible object; nothing when the scene shows nothing.
std::optional<Box> scene_bounds(const Document& doc);

// Translates `shape` along +x so its box starts a gap (a quarter of its own width, at least
// 0.5) past the visible objects' box, level with that box's centre in y; unchanged in an
// empty scene. An implicit surface moves with its formula: x, y, z become (x - dx), ...
// (translated, core/doc/kinds/implicit_kind.hpp).
void place_beside_scene(const Document& doc, Shape& shape);

// `wanted` when no object has that name, else the first of "wanted (2)", "wanted (3)", ...
// that none has (the object `except` does not count: a renamed or rebuilt object).
std::string unique_name(const Document& doc, const std::string& wanted, std::uint64_t except = 0);

} // namespace isoparm::doc
