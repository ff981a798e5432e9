// Scene files: indented text with exact numbers; reading and writing go through
// input_file.hpp and atomic_file.hpp.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <string_view>

#include "core/json/input_file.hpp"
#include "core/json/out_of_memory.hpp"
#include "core/json/reader.hpp"
#include "core/scene/atomic_file.hpp"
#include "core/scene/scene_io.hpp"

namespace isoparm::scene {

using namespace isoparm::doc;
using namespace isoparm::json_io;

using nlohmann::json;

namespace {

// ---------------------------------------------------------------------------------------
// Writing.

// Shortest round-trip text of a double that still reads back as a float and keeps the sign
// of zero: "0.5", "1.0", "-0.0", "1e-05", "1.5e+300".
void write_double(std::string& out, double x) {
    if (!std::isfinite(x)) {
        out += "null"; // never happens for a valid document; never write invalid JSON
        return;
    }
    std::array<char, 64> buf{};
    const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), x);
    const std::string_view s(buf.data(), static_cast<std::size_t>(res.ptr - buf.data()));
    out += s;
    if (s.find_first_of(".e") == std::string_view::npos) out += ".0";
}

void write_string(std::string& out, const std::string& s) {
    // Invalid UTF-8 cannot come from a loaded scene (the parser rejects it); anything else
    // is replaced rather than thrown on.
    out += json(s).dump(-1, ' ', false, json::error_handler_t::replace);
}

// Members in the order a reader looks for them; the rest alphabetically after.
constexpr std::array<std::string_view, 27> key_order = {
    "format",    "version", "id",        "name",       "kind",        "visible", "plane",
    "knot_mode", "surface", "curve",     "implicit",   "triangle",    "type",    "degree",
    "knots",     "points",  "weights",   "expression", "parameters",  "value",   "bounds",
    "cell",      "objects", "selection", "indicator",  "barycentric", "display"};

int key_rank(const std::string& k) {
    for (std::size_t r = 0; r < key_order.size(); ++r)
        if (k == key_order[r]) return static_cast<int>(r);
    return static_cast<int>(key_order.size());
}

std::vector<std::pair<const std::string*, const json*>> ordered_members(const json& o) {
    std::vector<std::pair<const std::string*, const json*>> members;
    for (auto it = o.begin(); it != o.end(); ++it) members.emplace_back(&it.key(), &it.value());
    // Only scenes, objects and geometry get the reading order; colours and display settings
    // (whose names overlap it: "surface", "indicator") stay alphabetical.
    if (!o.contains("format") && !o.contains("kind") && !o.contains("type") &&
        !o.contains("expression") && !o.contains("name"))
        return members;
    std::stable_sort(members.begin(), members.end(), [](const auto& a, const auto& b) {
        return key_rank(*a.first) < key_rank(*b.first); // std::map order breaks ties
    });
    return members;
}

// Appends v on one line. With a `limit`, stops as soon as `out` is longer than that and
// returns false: write_pretty only asks whether a container fits on a line, and must not
// format a 100 MB surface in full at every level of nesting to find out it does not.
bool write_compact(std::string& out, const json& v,
                   std::size_t limit = std::numeric_limits<std::size_t>::max()) {
    switch (v.type()) {
    case json::value_t::object: {
        out += '{';
        bool first = true;
        for (const auto& [k, m] : ordered_members(v)) {
            if (!first) out += ", ";
            first = false;
            write_string(out, *k);
            out += ": ";
            if (!write_compact(out, *m, limit)) return false;
        }
        out += '}';
        break;
    }
    case json::value_t::array: {
        out += '[';
        for (std::size_t k = 0; k < v.size(); ++k) {
            if (k) out += ", ";
            if (!write_compact(out, v[k], limit)) return false;
        }
        out += ']';
        break;
    }
    case json::value_t::number_float:
        write_double(out, v.get<double>());
        break;
    case json::value_t::string:
        write_string(out, v.get_ref<const std::string&>());
        break;
    default:
        out += v.dump();
        break; // null, booleans, integers
    }
    return out.size() <= limit;
}

// Containers that fit on a line stay on one line; others get one member per line, so a
// surface reads row by row.
void write_pretty(std::string& out, const json& v, int indent) {
    constexpr std::size_t line_budget = 96;
    if (!v.is_structured() || v.empty()) {
        write_compact(out, v);
        return;
    }
    const auto used = static_cast<std::size_t>(indent);
    if (indent > 0 && used <= line_budget) {
        std::string compact;
        if (write_compact(compact, v, line_budget - used)) {
            out += compact;
            return;
        }
    }
    const std::string pad(static_cast<std::size_t>(indent + 2), ' ');
    if (v.is_object()) {
        out += "{\n";
        bool first = true;
        for (const auto& [k, m] : ordered_members(v)) {
            if (!first) out += ",\n";
            first = false;
            out += pad;
            write_string(out, *k);
            out += ": ";
            write_pretty(out, *m, indent + 2);
        }
        out += '\n' + std::string(static_cast<std::size_t>(indent), ' ') + '}';
    } else {
        out += "[\n";
        for (std::size_t k = 0; k < v.size(); ++k) {
            if (k) out += ",\n";
            out += pad;
            write_pretty(out, v[k], indent + 2);
        }
        out += '\n' + std::string(static_cast<std::size_t>(indent), ' ') + ']';
    }
}

} // namespace

std::string pretty_json_text(const json& value) {
    std::string out;
    write_pretty(out, value, 0);
    out += '\n';
    return out;
}

std::string scene_to_text(const Document& doc) {
    std::string out;
    json tree = scene_to_json(doc);
    const ReleaseJsonOnExit release(tree); // freed without allocating, even out of memory
    write_pretty(out, tree, 0);
    out += '\n';
    return out;
}

namespace {

geom::Expected<Document> load_scene_text(const std::string& path) {
    auto read = read_input_file(path, max_input_bytes);
    if (!read) return read.error();
    std::string text = std::move(read).value();
    auto doc = scene_from_text(text);
    text.clear();
    text.shrink_to_fit();
    if (!doc && !doc.error().has_path && doc.error().code == geom::ErrorCode::parse) {
        geom::Error e = doc.error();
        e.message = "'" + path + "' is not JSON: " + e.message;
        return e;
    }
    return doc;
}

} // namespace

geom::Expected<Document> load_scene(const std::string& path) {
    arm_memory_reserve();
    try {
        return load_scene_text(path);
    } catch (const std::bad_alloc&) {
        arm_memory_reserve(); // the reserve let the unwinding finish; set a new one aside
        return geom::make_error_nopath(geom::ErrorCode::limit,
                                       "not enough memory to load '" + path + "'");
    }
}

geom::Status save_scene(const Document& doc, const std::string& path) {
    // Checked before the (possibly long) formatting: a directory or a device is refused at once.
    if (auto usable = check_output_path(path); !usable) return usable;
    arm_memory_reserve();
    try {
        return write_file_atomically(path, scene_to_text(doc));
    } catch (const std::bad_alloc&) {
        arm_memory_reserve();
        return geom::make_error_nopath(geom::ErrorCode::limit,
                                       "not enough memory to save '" + path + "'");
    }
}

} // namespace isoparm::scene
