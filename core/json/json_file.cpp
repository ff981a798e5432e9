#include "core/json/json_file.hpp"

#include "core/json/input_file.hpp"
#include "core/json/reader.hpp"

namespace isoparm::json_io {

geom::Expected<nlohmann::json> read_json_file(const std::string& path, std::uintmax_t max_bytes) {
    auto text = read_input_file(path, max_bytes);
    if (!text) return text.error();
    auto read = read_json(*text);
    if (!read) {
        geom::Error e = read.error();
        e.message = "'" + path + "' is not JSON: " + e.message;
        return e;
    }
    if (!read->problems.empty()) return read->problems.front();
    return std::move(read->value);
}

} // namespace isoparm::json_io
