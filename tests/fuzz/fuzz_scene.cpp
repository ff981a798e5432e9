// libFuzzer target: any bytes as a scene file. Loading answers a document or an error.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/json/reader.hpp"
#include "core/scene/scene_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto read = isoparm::json_io::read_json(text);
    if (!read.ok()) return 0;
    auto doc = isoparm::scene::scene_from_json(read->value);
    if (doc.ok()) {
        // A loaded scene saves and loads back (no value the loader accepts breaks the writer).
        auto again = isoparm::scene::scene_from_json(isoparm::scene::scene_to_json(*doc));
        if (!again.ok()) __builtin_trap();
    }
    return 0;
}
