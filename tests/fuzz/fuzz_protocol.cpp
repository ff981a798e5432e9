// libFuzzer target: any bytes as `isoparm geom` input. It must answer or reject, never crash,
// hang or allocate without bound.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/doc/protocol.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    std::ostringstream out, err;
    const int status = isoparm::doc::run_protocol(in, out, err);
    if (status < 0 || status > 2) __builtin_trap();
    // Exit 2 (not JSON) writes nothing to stdout.
    if (status == 2 && !out.str().empty()) __builtin_trap();
    return 0;
}
