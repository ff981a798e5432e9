// CSV / XYZ data points: one point per line, blank lines between the rows of a grid.
#include "core/scene/point_file.hpp"

#include <charconv>
#include <cmath>

#include "core/json/input_file.hpp"

namespace isoparm::scene {

namespace {

using geom::ErrorCode;
using geom::make_error;

bool is_separator(char c) {
    return c == ',' || c == ';' || c == ' ' || c == '\t' || c == '\r';
}

// The line's fields, split at separators (runs of them count once), comment removed.
std::vector<std::string_view> fields_of(std::string_view line) {
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
        line = line.substr(0, hash);
    std::vector<std::string_view> out;
    std::size_t k = 0;
    while (k < line.size()) {
        while (k < line.size() && is_separator(line[k])) ++k;
        const std::size_t start = k;
        while (k < line.size() && !is_separator(line[k])) ++k;
        if (k > start) out.push_back(line.substr(start, k - start));
    }
    return out;
}

// A whole field as a number (from_chars: the C locale, no leading '+').
bool parse_number(std::string_view field, double& value) {
    if (!field.empty() && field.front() == '+') field.remove_prefix(1);
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
    return ec == std::errc() && end == field.data() + field.size();
}

std::string quoted(std::string_view s) {
    constexpr std::size_t shown = 40;
    return "'" + std::string(s.substr(0, shown)) + (s.size() > shown ? "...'" : "'");
}

geom::Error at_line(std::size_t line, const std::string& message) {
    return make_error(ErrorCode::schema, "line " + std::to_string(line) + ": " + message);
}

} // namespace

geom::Expected<PointData> points_from_text(std::string_view text) {
    PointData out;
    std::vector<std::size_t> block_sizes{0};
    std::size_t first_count = 0, first_line = 0, line_no = 0;
    bool seen_content = false;
    while (!text.empty()) {
        ++line_no;
        const std::size_t nl = text.find('\n');
        const std::string_view line = text.substr(0, nl);
        text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
        const std::vector<std::string_view> fields = fields_of(line);
        if (fields.empty()) {
            // A blank line (not a comment-only one) ends a grid row.
            const bool blank = line.find('#') == std::string_view::npos;
            if (blank && block_sizes.back() > 0) block_sizes.push_back(0);
            continue;
        }
        double values[3] = {0, 0, 0};
        const bool header = !seen_content && !parse_number(fields[0], values[0]);
        seen_content = true;
        if (header) continue;
        if (fields.size() != 2 && fields.size() != 3)
            return at_line(line_no, std::to_string(fields.size()) +
                                        " numbers; a point is 2 (x y) or 3 (x y z)");
        for (std::size_t k = 0; k < fields.size(); ++k) {
            if (!parse_number(fields[k], values[k]))
                return at_line(line_no, quoted(fields[k]) + " is not a number");
            if (!std::isfinite(values[k]))
                return at_line(line_no, quoted(fields[k]) + " is not a finite number");
        }
        if (first_count == 0) {
            first_count = fields.size();
            first_line = line_no;
        } else if (fields.size() != first_count) {
            return at_line(line_no, std::to_string(fields.size()) + " numbers, but line " +
                                        std::to_string(first_line) + " has " +
                                        std::to_string(first_count));
        }
        if (out.points.size() >= max_data_points)
            return make_error(ErrorCode::limit, "more than " + std::to_string(max_data_points) +
                                                    " points (line " + std::to_string(line_no) +
                                                    ")");
        out.points.emplace_back(values[0], values[1], values[2]);
        ++block_sizes.back();
        if (block_sizes.size() > 1 && block_sizes.back() > block_sizes.front())
            return at_line(line_no, "grid row " + std::to_string(block_sizes.size()) +
                                        " is longer than row 1 (" +
                                        std::to_string(block_sizes.front()) + " points)");
    }
    if (block_sizes.back() == 0 && block_sizes.size() > 1) block_sizes.pop_back();
    if (out.points.empty())
        return make_error(ErrorCode::schema,
                          "no points: one point per line, x y or x y z (CSV or whitespace)");
    for (std::size_t r = 1; r < block_sizes.size(); ++r)
        if (block_sizes[r] != block_sizes.front())
            return make_error(ErrorCode::schema, "grid row " + std::to_string(r + 1) + " has " +
                                                     std::to_string(block_sizes[r]) +
                                                     " points, row 1 has " +
                                                     std::to_string(block_sizes.front()) +
                                                     " (blank lines separate the rows of a grid)");
    out.rows = static_cast<int>(block_sizes.size());
    out.columns = static_cast<int>(block_sizes.front());
    return out;
}

geom::Expected<PointData> load_points(const std::string& path) {
    auto text = json_io::read_input_file(path, max_point_file_bytes);
    if (!text) return text.error();
    auto data = points_from_text(*text);
    if (!data) {
        geom::Error e = data.error();
        e.message = "'" + path + "': " + e.message;
        return e;
    }
    return data;
}

} // namespace isoparm::scene
