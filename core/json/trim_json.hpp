// Trims <-> JSON: {"outer": [curve, ...], "holes": [[curve, ...], ...]}, each curve a 2D
// curve ({"type", "degree", "knots", "points": [[u, v], ...], "weights"}), shared by the
// protocol and scenes.
#pragma once

#include <nlohmann/json.hpp>

#include "core/geom/status.hpp"
#include "core/geom/trim/trim.hpp"

namespace isoparm::json_io {

// The loops and their curves (each curve_from_json's checks, points [u, v] only; an empty
// object is no trim). Paths are relative to j ("/holes/1/0/knots/3"). Whether the loops fit a
// surface's domain is geom::validate_trim's, which the caller runs with that domain.
geom::Expected<geom::Trim> trim_from_json(const nlohmann::json& j);
nlohmann::json trim_to_json(const geom::Trim& t);

// A parameter point [u, v] of finite numbers (`schema` at path).
geom::Expected<glm::dvec2> read_param(const nlohmann::json& v, const std::string& path);

} // namespace isoparm::json_io
