// Document commands as JSON (docs/commands.md): {"command": "<name>", ...its arguments}. The
// same member names as the paths the commands' refusals use ("/id", "/i", "/position/0"), so
// a refusal can be placed in the script step that caused it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/doc/command_spec.hpp"
#include "core/geom/status.hpp"

namespace isoparm::scene {

nlohmann::json command_to_json(const doc::CommandSpec& spec);
// Reads the JSON form strictly: unknown commands and members, missing members and wrong types
// are `schema` errors at their path under `at`. Whether the command applies to a document is
// the command's own check (doc::Command::check), not this reader's.
geom::Expected<doc::CommandSpec> command_from_json(const nlohmann::json& j,
                                                   const std::string& at = "");

} // namespace isoparm::scene
