#include "core/scene/starting_scene.hpp"

#include <filesystem>

#include "core/json/fields.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

geom::Expected<StartingScene> read_starting_scene(const nlohmann::json& scene,
                                                  const std::string& dir,
                                                  const std::string& named_by) {
    if (scene.is_string()) {
        const std::filesystem::path rel(scene.get<std::string>());
        const std::string path =
            rel.is_absolute() ? rel.string() : (std::filesystem::path(dir) / rel).string();
        auto loaded = load_scene(path);
        if (!loaded) {
            geom::Error e = loaded.error();
            e.message = "the starting scene '" + path + "': " + e.message +
                        (e.has_path && !e.path.empty() ? " (at " + e.path + " in that file)" : "");
            e.path = "/scene";
            e.has_path = true;
            return e;
        }
        return StartingScene{std::move(loaded).value(), path};
    }
    if (scene.is_object()) {
        auto inline_scene = scene_from_json(scene);
        if (!inline_scene) return inline_scene.error().under("/scene");
        return StartingScene{std::move(inline_scene).value(), "(inline)"};
    }
    return json_io::schema_error("scene is a path to a scene file (relative to " + named_by +
                                     ") or a scene written inline",
                                 "/scene");
}

} // namespace isoparm::scene
