// Data points for fitting, from CSV or XYZ text (the Fit panel's Load points).
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/geom/status.hpp"

namespace isoparm::scene {

// One point per line: 2 or 3 numbers (x y, or x y z) separated by commas, semicolons, spaces
// or tabs; every line the same count (2 numbers: z = 0). `#` starts a comment. A first line
// that is not numbers is a header ("x,y,z") and is skipped. Blank lines separate the rows of a
// grid (gnuplot's convention): with two or more blocks, `rows` blocks of `columns` points each,
// all the same length, in row-major order (a surface to interpolate); with one block, a curve's
// points (rows = 1). Errors (`schema`) name the line: "line 7: 'abc' is not a number", a count
// other than 2 or 3, a count that differs from the first point's, a non-finite number, rows of
// different lengths, no points, more than max_points.
struct PointData {
    std::vector<glm::dvec3> points;
    int rows = 1;
    int columns = 0;
    bool grid() const { return rows > 1; }
};

inline constexpr std::size_t max_data_points = 1'000'000;
inline constexpr std::size_t max_point_file_bytes = 64u << 20;

geom::Expected<PointData> points_from_text(std::string_view text);
// The file through read_input_file (a regular file, at most max_point_file_bytes); errors name
// the file.
geom::Expected<PointData> load_points(const std::string& path);

} // namespace isoparm::scene
