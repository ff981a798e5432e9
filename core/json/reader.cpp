// Reading untrusted JSON text through nlohmann's SAX interface (see reader.hpp).
#include "core/json/reader.hpp"

#include "core/json/out_of_memory.hpp"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <utility>

namespace isoparm::json_io {

using nlohmann::json;

std::string escape_pointer_token(std::string_view token) {
    std::string out;
    out.reserve(token.size());
    for (char c : token) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

std::string short_name(std::string_view name) {
    constexpr std::size_t max_bytes = 64;
    if (name.size() <= max_bytes) return std::string(name);
    std::size_t cut = max_bytes;
    // Back off UTF-8 continuation bytes (10xxxxxx) so the cut never splits a character.
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
    return std::string(name.substr(0, cut)) + "...";
}

std::vector<geom::Error> problems_under(const std::vector<geom::Error>& problems,
                                        const std::string& prefix) {
    std::vector<geom::Error> out;
    for (const geom::Error& p : problems) {
        if (prefix.empty()) {
            out.push_back(p);
        } else if (p.path == prefix || (p.path.size() > prefix.size() &&
                                        p.path.compare(0, prefix.size(), prefix) == 0 &&
                                        p.path[prefix.size()] == '/')) {
            geom::Error e = p;
            e.path = p.path.substr(prefix.size());
            out.push_back(std::move(e));
        }
    }
    return out;
}

namespace {

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

// RFC 8259 number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
bool is_json_number(std::string_view s) {
    std::size_t i = 0;
    const std::size_t n = s.size();
    if (i < n && s[i] == '-') ++i;
    if (i >= n) return false;
    if (s[i] == '0') {
        ++i;
    } else if (is_digit(s[i])) {
        while (i < n && is_digit(s[i])) ++i;
    } else {
        return false;
    }
    if (i < n && s[i] == '.') {
        ++i;
        if (i >= n || !is_digit(s[i])) return false;
        while (i < n && is_digit(s[i])) ++i;
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        ++i;
        if (i < n && (s[i] == '+' || s[i] == '-')) ++i;
        if (i >= n || !is_digit(s[i])) return false;
        while (i < n && is_digit(s[i])) ++i;
    }
    return i == n;
}

// A number token that overflows a double (nlohmann refuses those with error 406, but they
// are valid JSON and the protocol answers them as a `weights`/`schema` error instead).
struct OverflowToken {
    std::size_t offset = 0, length = 0;
    std::size_t ordinal = 0; // index among all number tokens, in text order
    bool negative = false;
};

// One linear pass outside strings. In valid JSON every maximal run of number characters
// outside a string is exactly one number token, so ordinals match the SAX number events.
std::vector<OverflowToken> find_overflows(std::string_view text) {
    std::vector<OverflowToken> found;
    std::size_t ordinal = 0;
    bool in_string = false;
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        const char c = text[i];
        if (in_string) {
            if (c == '\\')
                i += 2;
            else {
                if (c == '"') in_string = false;
                ++i;
            }
            continue;
        }
        if (c == '"') {
            in_string = true;
            ++i;
            continue;
        }
        if (c == '-' || is_digit(c)) {
            std::size_t j = i;
            while (j < n && (is_digit(text[j]) || text[j] == '-' || text[j] == '+' ||
                             text[j] == '.' || text[j] == 'e' || text[j] == 'E'))
                ++j;
            const std::string_view token = text.substr(i, j - i);
            if (is_json_number(token)) {
                const std::string copy(token);
                const double v = std::strtod(copy.c_str(), nullptr);
                if (std::isinf(v)) found.push_back({i, j - i, ordinal, token[0] == '-'});
                ++ordinal;
            }
            i = j;
            continue;
        }
        ++i;
    }
    return found;
}

// Builds the DOM like nlohmann's json_sax_dom_parser, plus the checks of reader.hpp.
// Skipped subtrees (a duplicate's value, a too-deep container) are only counted, not built.
class Builder {
public:
    explicit Builder(std::vector<OverflowToken> overflows) : overflows_(std::move(overflows)) {}

    bool null() { return scalar(json(nullptr)); }
    bool boolean(bool b) { return scalar(json(b)); }
    bool number_integer(json::number_integer_t v) { return number(json(v)); }
    bool number_unsigned(json::number_unsigned_t v) { return number(json(v)); }
    bool number_float(json::number_float_t v, const std::string& /*raw*/) {
        return number(json(v));
    }
    bool string(std::string& s) { return scalar(json(std::move(s))); }
    bool binary(json::binary_t& b) { return scalar(json::binary(std::move(b))); }
    bool start_object(std::size_t /*elements*/) { return open(json::value_t::object); }
    bool end_object() { return close(); }
    bool start_array(std::size_t /*elements*/) { return open(json::value_t::array); }
    bool end_array() { return close(); }

    bool key(std::string& k) {
        if (skip_depth_ > 0) return true;
        Frame& f = frames_.back();
        if (f.value->contains(k)) {
            problems_.push_back(geom::make_error(
                geom::ErrorCode::schema, "duplicate key '" + short_name(k) + "' in an object",
                current_path() + "/" + escape_pointer_token(k)));
            skip_next_ = true;
        }
        f.key = std::move(k);
        return true;
    }

    bool parse_error(std::size_t position, const std::string& /*last_token*/,
                     const nlohmann::detail::exception& ex) {
        error_position_ = position;
        error_what_ = ex.what();
        return false;
    }

    json root;
    bool too_many_values = false;
    std::vector<geom::Error> problems_;
    std::size_t error_position_ = 0;
    std::string error_what_;

private:
    struct Frame {
        json* value;
        std::string key;            // objects: the member being read
        std::size_t next_index = 0; // arrays: the index of the next element
    };

    bool number(json v) {
        const std::size_t ordinal = number_count_++;
        if (next_overflow_ < overflows_.size() && overflows_[next_overflow_].ordinal == ordinal) {
            const double inf = std::numeric_limits<double>::infinity();
            v = json(overflows_[next_overflow_].negative ? -inf : inf);
            ++next_overflow_;
        }
        return scalar(std::move(v));
    }

    bool scalar(json v) {
        if (skip_depth_ > 0) return true;
        if (skip_next_) {
            skip_next_ = false;
            return true;
        }
        if (!count_value()) return false;
        place(std::move(v));
        return true;
    }

    // Stops the parse (false) once the tree would hold more than max_json_values values.
    bool count_value() {
        if (++value_count_ <= max_json_values) return true;
        too_many_values = true;
        return false;
    }

    bool open(json::value_t type) {
        if (skip_depth_ > 0) {
            ++skip_depth_;
            return true;
        }
        if (skip_next_) {
            skip_next_ = false;
            skip_depth_ = 1;
            return true;
        }
        if (frames_.size() >= static_cast<std::size_t>(max_json_depth)) {
            problems_.push_back(geom::make_error(geom::ErrorCode::limit,
                                                 "the JSON nests deeper than " +
                                                     std::to_string(max_json_depth) + " levels",
                                                 child_path()));
            place(json(nullptr));
            skip_depth_ = 1;
            return true;
        }
        if (!count_value()) return false;
        json* slot = place(json(type));
        frames_.push_back(Frame{slot, {}, 0});
        return true;
    }

    bool close() {
        if (skip_depth_ > 0) {
            --skip_depth_;
            return true;
        }
        frames_.pop_back();
        return true;
    }

    json* place(json v) {
        if (frames_.empty()) {
            root = std::move(v);
            return &root;
        }
        Frame& f = frames_.back();
        if (f.value->is_array()) {
            auto& arr = f.value->get_ref<json::array_t&>();
            arr.push_back(std::move(v));
            ++f.next_index;
            return &arr.back();
        }
        auto& obj = f.value->get_ref<json::object_t&>();
        auto [it, inserted] = obj.emplace(f.key, std::move(v));
        return &it->second;
    }

    // The path of the innermost open container.
    std::string current_path() const {
        std::string path;
        for (std::size_t k = 1; k < frames_.size(); ++k) {
            const Frame& parent = frames_[k - 1];
            path += '/';
            path += parent.value->is_array() ? std::to_string(parent.next_index - 1)
                                             : escape_pointer_token(parent.key);
        }
        return path;
    }

    // The path of the value about to be placed in the innermost container.
    std::string child_path() const {
        if (frames_.empty()) return "";
        const Frame& top = frames_.back();
        return current_path() + "/" +
               (top.value->is_array() ? std::to_string(top.next_index)
                                      : escape_pointer_token(top.key));
    }

    std::vector<Frame> frames_;
    std::vector<OverflowToken> overflows_;
    std::size_t next_overflow_ = 0;
    std::size_t number_count_ = 0;
    std::size_t value_count_ = 0;
    int skip_depth_ = 0;
    bool skip_next_ = false;
};

// "parse error at line 3, column 7: syntax error ..." from nlohmann's message; if the
// message has no position, compute it from the byte offset.
std::string describe_parse_error(std::string_view text, std::size_t position,
                                 const std::string& what) {
    const std::size_t at = what.find("at line ");
    if (at != std::string::npos) return what.substr(at + 3);
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < position && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    std::string detail = what;
    const std::size_t bracket = detail.find("] ");
    if (bracket != std::string::npos) detail = detail.substr(bracket + 2);
    return "line " + std::to_string(line) + ", column " + std::to_string(column) + ": " + detail;
}

} // namespace

geom::Expected<ReadJson> read_json(std::string_view text) {
    std::vector<OverflowToken> overflows = find_overflows(text);
    std::string patched;
    std::string_view input = text;
    if (!overflows.empty()) {
        // Same length, so line and column of any later syntax error are unchanged.
        patched.assign(text);
        for (const OverflowToken& t : overflows) {
            patched[t.offset] = '0';
            for (std::size_t k = 1; k < t.length; ++k) patched[t.offset + k] = ' ';
        }
        input = patched;
    }
    Builder builder(std::move(overflows));
    bool ok = false;
    try {
        ok = json::sax_parse(input.data(), input.data() + input.size(), &builder);
    } catch (const std::bad_alloc&) {
        // The partial tree is emptied without allocating (out_of_memory.hpp says why that
        // matters), and a new reserve is set aside for whatever comes next.
        release_json(builder.root);
        arm_memory_reserve();
        return geom::make_error_nopath(geom::ErrorCode::limit,
                                       "not enough memory to read the input");
    } catch (const std::exception& e) {
        // The builder never throws on purpose.
        release_json(builder.root);
        return geom::make_error_nopath(geom::ErrorCode::limit,
                                       std::string("the input is too large: ") + e.what());
    }
    if (builder.too_many_values) {
        release_json(builder.root);
        return geom::make_error_nopath(
            geom::ErrorCode::limit, "the input holds more than " + std::to_string(max_json_values) +
                                        " JSON values (numbers, strings, arrays, objects); at "
                                        "most that many are read, about 1 GiB once parsed");
    }
    if (!ok) {
        std::string message =
            describe_parse_error(text, builder.error_position_, builder.error_what_);
        for (char& c : message)
            if (c == '\n' || c == '\r') c = ' ';
        return geom::make_error_nopath(geom::ErrorCode::parse, message);
    }
    return ReadJson{std::move(builder.root), std::move(builder.problems_)};
}

} // namespace isoparm::json_io
