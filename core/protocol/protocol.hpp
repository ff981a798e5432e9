// `isoparm geom`: the JSON geometry protocol (../shared/spec/geom-protocol.md).
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>

#include "core/geom/status.hpp"

namespace isoparm::protocol {

// One request object -> one response object ({"ok": true, ...} or {"ok": false, "error"}).
nlohmann::json handle_request(const nlohmann::json& request);

// Reads one request or a batch from `in`, writes the response(s) to `out`. Returns the exit
// status: 0 all succeeded, 1 some failed, 2 not JSON (message with line and column to err).
// The input is capped at max_input_bytes (input_file.hpp): more is one `limit` response, exit 1.
int run_protocol(std::istream& in, std::ostream& out, std::ostream& err);
// The same on text already read (the command line reads files and standard input itself, so a
// FIFO or a directory cannot block or abort it).
int run_protocol_text(std::string text, std::ostream& out, std::ostream& err);
// The response run_protocol writes when the input could not be taken whole (too large).
nlohmann::json input_error_response(const geom::Error& e);

} // namespace isoparm::protocol
