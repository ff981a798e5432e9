// The "scene" member that scripts, lessons and exercises start from: a path to a scene file
// (relative to the file that names it) or a scene written inline.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::scene {

struct StartingScene {
    doc::Document document;
    std::string name; // the scene file's path, or "(inline)"
};

// `scene` is the member's value, found at "/scene"; `dir` is the naming file's folder and
// `named_by` says what names it in errors ("the script", "the exercise"). A file that does not
// load is an error at "/scene" that names the file (and where in it the problem is).
geom::Expected<StartingScene> read_starting_scene(const nlohmann::json& scene,
                                                  const std::string& dir,
                                                  const std::string& named_by);

} // namespace isoparm::scene
