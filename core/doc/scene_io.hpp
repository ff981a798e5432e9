// Scenes as JSON (docs/scene-format.md): load with precise errors, save atomically.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::doc {

nlohmann::json scene_to_json(const Document& doc);
// Errors name the offending value with a JSON Pointer into the scene.
geom::Expected<Document> scene_from_json(const nlohmann::json& j);

geom::Expected<Document> load_scene(const std::string& path);
// Writes a temporary file beside the target, flushes it, then renames it over the target:
// a crash never leaves a half-written scene.
geom::Status save_scene(const Document& doc, const std::string& path);

} // namespace isoparm::doc
