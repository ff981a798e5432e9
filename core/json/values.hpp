// Small readers of JSON scalars shared by the geometry parser and the protocol.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>

namespace isoparm::json_io {

// A number (not a boolean) with a finite value; 1e999 is read as inf and fails here.
inline bool is_finite_number(const nlohmann::json& v) {
    return v.is_number() && std::isfinite(v.get<double>());
}

// An integer, or a float with an integral value (3.0; the reference writes floats), as a
// saturated 64-bit value so that 1e300 stays "very large" instead of overflowing.
inline std::optional<std::int64_t> integer_value(const nlohmann::json& v) {
    if (v.is_number_integer() && !v.is_number_unsigned()) return v.get<std::int64_t>();
    if (v.is_number_unsigned()) {
        const auto u = v.get<std::uint64_t>();
        constexpr auto max = static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
        return static_cast<std::int64_t>(u > max ? max : u);
    }
    if (v.is_number_float()) {
        const double x = v.get<double>();
        if (!std::isfinite(x) || std::floor(x) != x) return std::nullopt;
        if (x >= 9.0e18) return std::numeric_limits<std::int64_t>::max();
        if (x <= -9.0e18) return std::numeric_limits<std::int64_t>::min();
        return static_cast<std::int64_t>(x);
    }
    return std::nullopt;
}

} // namespace isoparm::json_io
