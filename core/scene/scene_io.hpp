// Scenes as JSON (docs/scene-format.md): load with precise errors, save atomically.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "core/doc/document.hpp"
#include "core/geom/status.hpp"

namespace isoparm::scene {

// The scene format's name and the newest version this build reads and writes. Version 2 added
// an object's own display toggles ("display" in the object) and its "construction" (a recipe
// that keeps it linked to its inputs); a scene is written as version 1 while none of its
// objects has either, so that it stays readable by older builds. Version 3 added a surface's
// "trim" (its trim loops), written only by scenes with a trimmed surface.
inline constexpr const char* scene_format_name = "isoparm-scene";
inline constexpr int scene_format_version = 3;
// The largest object (and patch group) id a file or command may name: 2^53, exact in every
// JSON reader.
inline constexpr std::uint64_t max_object_id = 9007199254740992ull;

nlohmann::json scene_to_json(const doc::Document& doc);
// Errors name the offending value with a JSON Pointer into the scene.
geom::Expected<doc::Document> scene_from_json(const nlohmann::json& j);

// The parts of a scene that commands carry too (core/scene/command_json.hpp), written and read
// by the same code as in a scene: an object, its shape alone ({"kind": ..., and the kind's
// geometry member: "surface", "curve" with "plane" and "knot_mode", or "implicit"}), and the
// colours (members missing from the JSON keep their value in `colors`). Errors are paths under
// `at`.
nlohmann::json object_to_json(const doc::Object& object);
geom::Expected<doc::Object> object_from_json(const nlohmann::json& j, const std::string& at);
nlohmann::json shape_to_json(const doc::Shape& shape);
geom::Expected<doc::Shape> shape_from_json(const nlohmann::json& j, const std::string& at);
nlohmann::json colors_to_json(const doc::Colors& colors);
geom::Expected<doc::Colors> colors_from_json(const nlohmann::json& j, const std::string& at,
                                             doc::Colors colors);
// The view state's parts, as a scene file writes them (scripts set them step by step): display
// settings (members missing keep their value in `current`), the selection ({"object": id,
// "point": [i, j] or [i]} or null; the object and point must exist in `doc`), the indicator
// ([u, v] in [0, 1]^2 over the current domain) and the continuity setting ("off", "C0", "C1").
// An object's own display toggles (format version 2): control_points, control_net,
// point_ids, knot_curves; members not named keep the value in `current`.
nlohmann::json object_display_to_json(const doc::ObjectDisplay& display);
geom::Expected<doc::ObjectDisplay> object_display_from_json(const nlohmann::json& j,
                                                            const std::string& at,
                                                            doc::ObjectDisplay current);
nlohmann::json display_to_json(const doc::DisplaySettings& display);
geom::Expected<doc::DisplaySettings>
display_from_json(const nlohmann::json& j, const std::string& at, doc::DisplaySettings current);
// {"object": id, "point": [i, j] or [i]}, or null when nothing is selected.
nlohmann::json selection_to_json(const doc::Selection& selection);
geom::Expected<doc::Selection> selection_from_json(const nlohmann::json& j, const std::string& at,
                                                   const doc::Document& doc);
geom::Expected<glm::dvec2> indicator_from_json(const nlohmann::json& j, const std::string& at);
// A triangle's indicator [r, s, t]: finite, each >= 0, summing to 1 within 1e-12 (`schema`).
geom::Expected<geom::Barycentric> barycentric_from_json(const nlohmann::json& j,
                                                        const std::string& at);
geom::Expected<doc::Continuity> continuity_from_json(const nlohmann::json& j,
                                                     const std::string& at);

// The text save_scene writes: indented for people, every number in shortest round-trip form
// (so a load gives back the same bits, -0.0 included), ending with a newline.
std::string scene_to_text(const doc::Document& doc);
// Any JSON value written the way scenes are (scripts and recordings use it too).
std::string pretty_json_text(const nlohmann::json& value);
// Parses scene text: not JSON (`parse`, message with line and column), duplicate keys
// (`schema`), nesting too deep (`limit`), then scene_from_json. Never throws, never crashes:
// this is the entry point the scene fuzzer drives.
geom::Expected<doc::Document> scene_from_text(std::string_view text);

// Reads and parses a scene file through read_input_file: only a regular file is read (a FIFO
// or a directory is refused without blocking). A file that cannot be read is `internal` without
// a path (the message names the file and the reason); files above 256 MiB are `limit`.
geom::Expected<doc::Document> load_scene(const std::string& path);
// Writes the scene with write_file_atomically (atomic_file.hpp): a crash never leaves a
// half-written scene; only a regular file (or "-") is written; a symbolic link is followed only
// where the kernel allows it; on any failure (`internal`, naming the file and the reason) the
// old file is intact and no temporary file is left.
geom::Status save_scene(const doc::Document& doc, const std::string& path);

} // namespace isoparm::scene
