// Writing responses: numbers in shortest round-trip form, floats always look like floats.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace isoparm::json_io {

// Shortest text that reads back as exactly x (std::to_chars), formatted like Python's repr
// (the reference): "0.5", "1.0", "1e-05", "1.5e+16"; zero is "0.0" whatever its sign.
// Precondition: x is finite.
std::string format_double(double x);
void append_double(std::string& out, double x);

// Compact one-line JSON. Floats through format_double, integers as integers. Objects write
// the members a reader looks for first ("ok", "error", then a geometry's type, degree,
// knots, points, weights, then results) in a fixed order, the rest alphabetically.
// Precondition: no NaN or infinity anywhere (a point that does not exist is null).
void write_json(std::string& out, const nlohmann::json& value);
std::string to_json_text(const nlohmann::json& value);

} // namespace isoparm::json_io
