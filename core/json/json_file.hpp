// A JSON file read whole (scripts, exercises): the file's own errors, then the text's.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

#include "core/geom/status.hpp"

namespace isoparm::json_io {

// The JSON value of the regular file at `path` (at most max_bytes, read_input_file): an error
// when it cannot be read, is not JSON ("'path' is not JSON: line 3, column 5: ...") or has a
// problem read_json reports (a duplicate key, nesting too deep: the first one).
geom::Expected<nlohmann::json> read_json_file(const std::string& path, std::uintmax_t max_bytes);

} // namespace isoparm::json_io
