// Reading untrusted JSON text: depth limit, duplicate keys, overflowing numbers kept as inf.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/geom/status.hpp"

namespace isoparm::json_io {

// Deeper nesting than this is a `limit` problem (the builder keeps going without recursion,
// so hostile input cannot exhaust the stack).
constexpr int max_json_depth = 256;

// More values than this (numbers, strings, booleans, nulls, arrays, objects, counted as read)
// stop the reader with a `limit` error without a path: the tree would pass the work budget's
// 1 GiB (work_budget.hpp; ~50 bytes a value). A 256 MiB input could otherwise become a
// 9 GB tree before anything looks at it. The largest geometry the spec allows (1,000,000
// points with weights) is ~5 million values.
constexpr std::size_t max_json_values = std::size_t{1} << 24;

// Text that is valid JSON, with the problems found in it that make it an unacceptable
// request. Each problem's path is absolute (from the root of the text), in text order:
// - a duplicate key: `schema`, path to the repeated member (the first value is kept);
// - nesting deeper than max_json_depth: `limit`, path to the first too-deep container
//   (it is replaced by null).
// Numbers that overflow a double (1e999, -1e999) are valid JSON: they are stored as +-inf
// doubles and not reported here, so validation can give the code the context calls for.
struct ReadJson {
    nlohmann::json value;
    std::vector<geom::Error> problems;
};

// Not JSON at all: the error's message is one line naming the line and column.
geom::Expected<ReadJson> read_json(std::string_view text);

// The problems (from ReadJson) inside the value at `prefix` ("" = the root, "/3" = batch
// element 3), with paths made relative to it.
std::vector<geom::Error> problems_under(const std::vector<geom::Error>& problems,
                                        const std::string& prefix);

// A member name or op name as messages quote it: at most 64 bytes (cut on a UTF-8
// character boundary, "..." appended), so a hostile 1 MB key does not become a 1 MB message.
std::string short_name(std::string_view name);

// One JSON Pointer reference token: "~" -> "~0", "/" -> "~1" (RFC 6901).
std::string escape_pointer_token(std::string_view token);

} // namespace isoparm::json_io
