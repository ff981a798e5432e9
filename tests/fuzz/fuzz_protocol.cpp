// libFuzzer target: any bytes as `isoparm geom` input. It must answer or reject, never crash.
//
// Volume is not this target's subject. Answers are bounded (docs/protocol.md, "Size caps of
// answers": at most 1,000,000 mesh vertices and 2,000,000 triangles, `limit` beyond; tested in
// tests/protocol/output_caps_test.cpp), but an answer at the caps still takes seconds and
// ~0.7 GB (several times that under ASan, past libFuzzer's RSS limit). Requests whose work
// would be large (tessellate samples or a polygonize grid above volume_cap points) are skipped
// so that a short run explores the logic rather than waiting on big answers; no request can
// now grow without bound, so the skip is about speed only.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "core/protocol/protocol.hpp"

namespace {

constexpr double volume_cap = 250000;

double number_or(const nlohmann::json& j, double fallback) {
    return j.is_number() ? j.get<double>() : fallback;
}

// True when one request asks for a large mesh (conservatively: anything unreadable is small).
bool large_request(const nlohmann::json& r) {
    if (!r.is_object()) return false;
    const auto op = r.find("op");
    if (op == r.end() || !op->is_string()) return false;
    if (*op == "tessellate") {
        const auto s = r.find("samples");
        if (s == r.end() || !s->is_array() || s->size() != 2) return false;
        return std::abs(number_or((*s)[0], 0)) * std::abs(number_or((*s)[1], 0)) > volume_cap;
    }
    if (*op == "polygonize") {
        const auto b = r.find("bounds");
        const auto c = r.find("cell");
        if (b == r.end() || c == r.end() || !b->is_array() || b->size() != 2) return false;
        const double cell = number_or(*c, 0);
        if (!(cell > 0)) return false;
        double points = 1;
        for (int k = 0; k < 3; ++k) {
            if (!(*b)[0].is_array() || !(*b)[1].is_array() || (*b)[0].size() != 3 ||
                (*b)[1].size() != 3)
                return false;
            const double extent = number_or((*b)[1][k], 0) - number_or((*b)[0][k], 0);
            points *= std::abs(extent) / cell + 2;
        }
        return !(points <= volume_cap);
    }
    return false;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (!parsed.is_discarded()) {
        if (large_request(parsed)) return 0;
        if (parsed.is_array())
            for (const auto& r : parsed)
                if (large_request(r)) return 0;
    }
    std::istringstream in(text);
    std::ostringstream out, err;
    const int status = isoparm::protocol::run_protocol(in, out, err);
    if (status < 0 || status > 2) __builtin_trap();
    // Exit 2 (not JSON) writes nothing to stdout.
    if (status == 2 && !out.str().empty()) __builtin_trap();
    return 0;
}
