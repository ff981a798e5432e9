#include "core/json/fields.hpp"

#include "core/json/reader.hpp"

namespace isoparm::json_io {

using nlohmann::json;

geom::Error schema_error(std::string message, std::string path) {
    return geom::make_error(geom::ErrorCode::schema, std::move(message), std::move(path));
}

std::string member_path(std::string_view at, std::string_view key) {
    return std::string(at) + "/" + escape_pointer_token(key);
}

const char* type_name(const json& v) {
    switch (v.type()) {
    case json::value_t::null:
        return "null";
    case json::value_t::boolean:
        return "a boolean";
    case json::value_t::string:
        return "a string";
    case json::value_t::array:
        return "an array";
    case json::value_t::object:
        return "an object";
    case json::value_t::binary:
        return "binary data";
    case json::value_t::discarded:
        return "nothing";
    default:
        return "a number";
    }
}

geom::Status check_members(const json& object, std::string_view at, std::string_view what,
                           std::span<const std::string_view> allowed) {
    for (const auto& item : object.items()) {
        bool known = false;
        for (std::string_view a : allowed) known = known || item.key() == a;
        if (known) continue;
        std::string list;
        for (std::string_view a : allowed) {
            if (!list.empty()) list += ", ";
            list += a;
        }
        // short_name: a hostile 1 MB key must not become a 1 MB message.
        return schema_error("unknown member '" + short_name(item.key()) + "' in " +
                                std::string(what) + " (allowed: " + list + ")",
                            member_path(at, item.key()));
    }
    return geom::Ok{};
}

geom::Status check_members(const json& object, std::string_view at, std::string_view what,
                           std::initializer_list<std::string_view> allowed) {
    return check_members(object, at, what, std::span(allowed.begin(), allowed.size()));
}

geom::Error missing_member(std::string_view at, std::string_view name) {
    return schema_error("missing member '" + std::string(name) + "'", member_path(at, name));
}

const json* find_member(const json& object, std::string_view name) {
    const auto it = object.find(std::string(name));
    return it == object.end() ? nullptr : &*it;
}

geom::Status expect_object(const json& v, const std::string& path, std::string_view what) {
    if (v.is_object()) return geom::Ok{};
    return schema_error(std::string(what) + " must be a JSON object, got " + type_name(v), path);
}

geom::Expected<double> read_finite(const json& v, const std::string& path, std::string_view what) {
    if (!v.is_number())
        return schema_error(std::string(what) + " must be a number, got " + type_name(v), path);
    const double x = v.get<double>();
    if (!std::isfinite(x))
        return schema_error(
            std::string(what) + " must be a finite number, got " + geom::format_number(x), path);
    return x;
}

geom::Expected<std::int64_t> read_integer(const json& v, const std::string& path,
                                          std::string_view what, std::int64_t lo, std::int64_t hi) {
    const std::optional<std::int64_t> n = integer_value(v);
    if (!n)
        return schema_error(std::string(what) + " must be an integer, got " +
                                (v.is_number() ? v.dump() : std::string(type_name(v))),
                            path);
    if (*n < lo || *n > hi)
        return schema_error(std::string(what) + " must be between " + std::to_string(lo) + " and " +
                                std::to_string(hi) + ", got " + std::to_string(*n),
                            path);
    return *n;
}

geom::Expected<bool> read_bool(const json& v, const std::string& path) {
    if (!v.is_boolean())
        return schema_error("expected true or false, got " + std::string(type_name(v)), path);
    return v.get<bool>();
}

geom::Expected<std::string> read_string(const json& v, const std::string& path,
                                        std::string_view what) {
    if (!v.is_string())
        return schema_error(std::string(what) + " must be a string, got " + type_name(v), path);
    return v.get<std::string>();
}

} // namespace isoparm::json_io
