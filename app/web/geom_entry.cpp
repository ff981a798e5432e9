// `isoparm geom` for web pages: one C function, wrapped in JavaScript by geom_api.js as
// `request(text) -> text`. The same protocol and the same answers as the command line
// (core/protocol), byte for byte: a request object or a batch array in, the response line(s)
// out. Linked into isoparm-geom.js (the geometry alone) and into the workstation's page.
#include <emscripten/emscripten.h>

#include <sstream>
#include <string>

#include "core/protocol/protocol.hpp"

namespace {

// The last answer, kept until the next call (JavaScript copies it out at once).
std::string& answer() {
    static std::string text;
    return text;
}

} // namespace

extern "C" {

// Answers `request` (UTF-8 JSON). The text returned is what `isoparm geom` writes to standard
// output; *status is its exit status (0 all ok, 1 some request failed, 2 not JSON, when the
// text is the message the command line writes to standard error).
EMSCRIPTEN_KEEPALIVE const char* isoparm_geom(const char* request, int* status) {
    std::ostringstream out, err;
    const int code = isoparm::protocol::run_protocol_text(request ? request : "", out, err);
    answer() = code == 2 ? err.str() : out.str();
    if (status) *status = code;
    return answer().c_str();
}

} // extern "C"
