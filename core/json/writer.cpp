// Writing responses with shortest round-trip numbers (see writer.hpp).
#include "core/json/writer.hpp"

#include <array>
#include <cassert>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace isoparm::json_io {

using nlohmann::json;

void append_double(std::string& out, double x) {
    assert(std::isfinite(x));
    if (!std::isfinite(x) || x == 0.0) {
        // Zero is "0.0" whatever its sign (a sign on zero only confuses a reader); release
        // builds write a non-finite value as null rather than invalid JSON.
        out += std::isfinite(x) ? "0.0" : "null";
        return;
    }
    // Shortest round-trip digits in scientific form: "-d.ddde+XX".
    std::array<char, 64> buf{};
    const auto res =
        std::to_chars(buf.data(), buf.data() + buf.size(), x, std::chars_format::scientific);
    const char* p = buf.data();
    const char* end = res.ptr;
    if (*p == '-') {
        out += '-';
        ++p;
    }
    std::array<char, 32> digits{};
    int n = 0;
    for (; p < end && *p != 'e'; ++p)
        if (*p != '.') digits[static_cast<std::size_t>(n++)] = *p;
    int exponent = 0;
    bool negative_exponent = false;
    for (++p; p < end; ++p) {
        if (*p == '-')
            negative_exponent = true;
        else if (*p != '+')
            exponent = exponent * 10 + (*p - '0');
    }
    if (negative_exponent) exponent = -exponent;
    const std::string_view d(digits.data(), static_cast<std::size_t>(n));
    if (exponent >= -4 && exponent < 16) {
        // Fixed notation where repr uses it (1e-04 <= |x| < 1e16); ".0" marks integral floats.
        if (exponent < 0) {
            out += "0.";
            out.append(static_cast<std::size_t>(-exponent - 1), '0');
            out += d;
        } else if (exponent + 1 >= n) {
            out += d;
            out.append(static_cast<std::size_t>(exponent + 1 - n), '0');
            out += ".0";
        } else {
            out += d.substr(0, static_cast<std::size_t>(exponent + 1));
            out += '.';
            out += d.substr(static_cast<std::size_t>(exponent + 1));
        }
        return;
    }
    out += d[0];
    if (n > 1) {
        out += '.';
        out += d.substr(1);
    }
    out += 'e';
    out += exponent < 0 ? '-' : '+';
    const int a = std::abs(exponent);
    if (a < 10) out += '0';
    out += std::to_string(a);
}

std::string format_double(double x) {
    std::string out;
    append_double(out, x);
    return out;
}

namespace {

// Members in reading order: status first, then a geometry's defining fields, then results.
constexpr std::array<std::string_view, 22> preferred_keys = {
    "ok",     "error",       "code",      "message",     "path",    "type",
    "degree", "knots",       "points",    "weights",     "curve",   "surface",
    "pieces", "values",      "positions", "derivatives", "normals", "triangles",
    "levels", "first_index", "u_stage",   "v_stage"};

template <class Int> void append_integer(std::string& out, Int k) {
    std::array<char, 24> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), k);
    out.append(buf.data(), res.ptr);
}

void write_string(std::string& out, const std::string& s) {
    out += json(s).dump(-1, ' ', false, json::error_handler_t::replace);
}

void write_value(std::string& out, const json& v) {
    switch (v.type()) {
    case json::value_t::null:
    case json::value_t::discarded:
        out += "null";
        return;
    case json::value_t::boolean:
        out += v.get<bool>() ? "true" : "false";
        return;
    case json::value_t::number_integer:
        append_integer(out, v.get<json::number_integer_t>());
        return;
    case json::value_t::number_unsigned:
        append_integer(out, v.get<json::number_unsigned_t>());
        return;
    case json::value_t::number_float:
        append_double(out, v.get<double>());
        return;
    case json::value_t::string:
        write_string(out, v.get_ref<const std::string&>());
        return;
    case json::value_t::binary:
        out += "null";
        return;
    case json::value_t::array: {
        out += '[';
        bool first = true;
        for (const json& e : v) {
            if (!first) out += ", ";
            first = false;
            write_value(out, e);
        }
        out += ']';
        return;
    }
    case json::value_t::object: {
        out += '{';
        bool first = true;
        auto member = [&](const std::string& key, const json& value) {
            if (!first) out += ", ";
            first = false;
            write_string(out, key);
            out += ": ";
            write_value(out, value);
        };
        const auto& obj = v.get_ref<const json::object_t&>();
        for (std::string_view key : preferred_keys) {
            auto it = obj.find(std::string(key));
            if (it != obj.end()) member(it->first, it->second);
        }
        for (const auto& [key, value] : obj) {
            bool preferred = false;
            for (std::string_view p : preferred_keys) preferred = preferred || key == p;
            if (!preferred) member(key, value);
        }
        out += '}';
        return;
    }
    }
}

} // namespace

void write_json(std::string& out, const json& value) {
    write_value(out, value);
}

std::string to_json_text(const json& value) {
    std::string out;
    write_value(out, value);
    return out;
}

} // namespace isoparm::json_io
