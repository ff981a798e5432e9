// libFuzzer target: any bytes as a script. Reading answers a script or an error; a script that
// reads runs (dry, with no screenshots) to its end or to a refused step, and every command step
// written back as JSON reads back to the same JSON.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/json/reader.hpp"
#include "core/scene/command_json.hpp"
#include "core/scene/script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto read = isoparm::json_io::read_json(text);
    if (!read.ok() || !read->problems.empty()) return 0;
    // Scene paths resolve in a folder that does not exist: only inline scenes load.
    auto script = isoparm::scene::script_from_json(read->value, "/nonexistent");
    if (!script.ok()) return 0;
    for (const isoparm::scene::Step& step : script->steps) {
        const auto* spec = std::get_if<isoparm::doc::CommandSpec>(&step.action);
        if (!spec) continue;
        const nlohmann::json written = isoparm::scene::command_to_json(*spec);
        auto again = isoparm::scene::command_from_json(written);
        if (!again.ok() || isoparm::scene::command_to_json(*again) != written) __builtin_trap();
    }
    if (script->steps.size() > 64) return 0; // each step is bounded; many of them take long
    isoparm::scene::ScriptState state(script->start);
    isoparm::scene::run_script(*script, state, {}, /*dry_run=*/true);
    return 0;
}
