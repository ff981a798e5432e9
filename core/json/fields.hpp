// The one set of field readers for everything read from JSON (requests, geometry, scenes,
// commands): every refusal is a `schema` error at the JSON Pointer of the offending value,
// worded the same way wherever it happens.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "core/geom/status.hpp"

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

// The enumeration value a JSON string names (geom::parse_name); nothing for other text or any
// other JSON type. Callers word the refusal: it lists what that place accepts.
template <class E> std::optional<E> enum_value(const nlohmann::json& v) {
    if (!v.is_string()) return std::nullopt;
    return geom::parse_name<E>(v.get_ref<const std::string&>());
}

// A `schema` error: the value at `path` breaks the rule the message states.
geom::Error schema_error(std::string message, std::string path);
// The path of member `key` of the object at `at` ("/objects/2" + "name"), escaped (RFC 6901).
std::string member_path(std::string_view at, std::string_view key);
// How messages name a value's JSON type: "null", "a boolean", "a number", "a string", ...
const char* type_name(const nlohmann::json& v);

// Members outside `allowed` are typos or from a newer isoparm: refused, never ignored.
// "unknown member 'colour' in a curve (allowed: type, degree, knots, points, weights)", at
// the member; `what` names the object ("a curve", "op 'evaluate'", "the scene").
geom::Status check_members(const nlohmann::json& object, std::string_view at, std::string_view what,
                           std::span<const std::string_view> allowed);
geom::Status check_members(const nlohmann::json& object, std::string_view at, std::string_view what,
                           std::initializer_list<std::string_view> allowed);
// "missing member 'degree'", at the path where the member would be.
geom::Error missing_member(std::string_view at, std::string_view name);
// The member, or nullptr when absent.
const nlohmann::json* find_member(const nlohmann::json& object, std::string_view name);

// "<what> must be a JSON object, got an array".
geom::Status expect_object(const nlohmann::json& v, const std::string& path, std::string_view what);
// A finite number: "<what> must be a number, got a string"; "<what> must be a finite number,
// got inf" (1e999 is read as infinity).
geom::Expected<double> read_finite(const nlohmann::json& v, const std::string& path,
                                   std::string_view what);
// An integer (integral floats such as 3.0 accepted) in [lo, hi]: "<what> must be an integer,
// got 2.5"; "<what> must be between 1 and 64, got 99".
geom::Expected<std::int64_t> read_integer(const nlohmann::json& v, const std::string& path,
                                          std::string_view what, std::int64_t lo, std::int64_t hi);
geom::Expected<bool> read_bool(const nlohmann::json& v, const std::string& path);
geom::Expected<std::string> read_string(const nlohmann::json& v, const std::string& path,
                                        std::string_view what);

} // namespace isoparm::json_io
