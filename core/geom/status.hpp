// Error reporting for user data: a code, one readable sentence, and a JSON Pointer
// (relative to the value the function was given) naming the offending value.
#pragma once

#include <string>
#include <utility>
#include <variant>

#include "core/geom/enum_names.hpp"

namespace isoparm::geom {

enum class ErrorCode {
    parse,
    schema,
    knots,
    degree,
    weights,
    domain,
    multiplicity,
    compatibility,
    geometry,
    limit,
    unknown_op,
    internal,
};

// As answers and messages name them: "parse", "schema", ..., "unknown_op", "internal".
inline constexpr EnumName<ErrorCode> error_code_names[] = {
    {ErrorCode::parse, "parse"},
    {ErrorCode::schema, "schema"},
    {ErrorCode::knots, "knots"},
    {ErrorCode::degree, "degree"},
    {ErrorCode::weights, "weights"},
    {ErrorCode::domain, "domain"},
    {ErrorCode::multiplicity, "multiplicity"},
    {ErrorCode::compatibility, "compatibility"},
    {ErrorCode::geometry, "geometry"},
    {ErrorCode::limit, "limit"},
    {ErrorCode::unknown_op, "unknown_op"},
    {ErrorCode::internal, "internal"},
};
static_assert(in_declaration_order(error_code_names));
constexpr std::span<const EnumName<ErrorCode>> enum_names(ErrorCode) {
    return error_code_names;
}

struct Error {
    ErrorCode code = ErrorCode::internal;
    std::string message;
    // JSON Pointer relative to the object the failing function was given ("" = the object
    // itself, or no single value at fault when has_path is false).
    std::string path;
    bool has_path = true;

    // The same error seen from a containing object: prefix is e.g. "/curve".
    Error under(const std::string& prefix) const {
        Error e = *this;
        if (e.has_path) e.path = prefix + e.path;
        return e;
    }
};

inline Error make_error(ErrorCode code, std::string message, std::string path = "") {
    return Error{code, std::move(message), std::move(path), true};
}
inline Error make_error_nopath(ErrorCode code, std::string message) {
    return Error{code, std::move(message), "", false};
}

// A value or an error (C++20 has no std::expected).
template <class T> class Expected {
public:
    Expected(T value) : v_(std::move(value)) {}
    Expected(Error error) : v_(std::move(error)) {}
    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }
    T& value() & { return std::get<0>(v_); }
    const T& value() const& { return std::get<0>(v_); }
    T&& value() && { return std::get<0>(std::move(v_)); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    const Error& error() const { return std::get<1>(v_); }

private:
    std::variant<T, Error> v_;
};

struct Ok {};
using Status = Expected<Ok>;

// The JSON Pointer step "/k" for an array index.
inline std::string pointer_step(long k) {
    std::string s("/");
    s.append(std::to_string(k));
    return s;
}

// Shortest round-trip text of a double, for messages ("0.4", "1e-09").
std::string format_number(double x);
// `digits` significant digits, for labels a person reads ("0.3333", not 0.3333333333333333).
std::string format_short(double x, int digits = 4);

} // namespace isoparm::geom
