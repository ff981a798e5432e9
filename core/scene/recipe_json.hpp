// A construction's recipe as JSON: the "construction" member of a scene object and of the
// construct and edit_construction commands (docs/scene-format.md, "Constructions").
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/doc/recipe.hpp"
#include "core/geom/status.hpp"

namespace isoparm::scene {

// {"operation": "revolve", "inputs": [2], "angle": 360}: the operation, the input ids in
// order and every parameter of that operation (defaults written too), then "refinements"
// where there are any.
nlohmann::json recipe_to_json(const doc::Recipe& recipe);
// Strict: "operation" and "inputs" required, a parameter of another operation refused
// ("angle is a parameter of revolve, not of skin"), each value checked for its type and range
// as far as reading can (the document's checks come when it is built). Errors under `at`.
geom::Expected<doc::Recipe> recipe_from_json(const nlohmann::json& j, const std::string& at);

} // namespace isoparm::scene
