// `isoparm geom`: the JSON geometry protocol (../shared/spec/geom-protocol.md).
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>

namespace isoparm::doc {

// One request object -> one response object ({"ok": true, ...} or {"ok": false, "error"}).
nlohmann::json handle_request(const nlohmann::json& request);

// Reads one request or a batch from `in`, writes the response(s) to `out`. Returns the exit
// status: 0 all succeeded, 1 some failed, 2 not JSON (message with line and column to err).
int run_protocol(std::istream& in, std::ostream& out, std::ostream& err);

} // namespace isoparm::doc
