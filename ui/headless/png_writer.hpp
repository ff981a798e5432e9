// Writing RGBA pictures as PNG, atomically: a temporary file renamed over the target, so a
// failure never leaves a partial PNG.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace isoparm::ui {

// rgba: width * height * 4 bytes, first row at the top. Returns "" or the reason it failed.
std::string write_png(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba);

} // namespace isoparm::ui
