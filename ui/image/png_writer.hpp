// Writing RGBA pictures as PNG through scene::write_file_atomically: a failure (full disk, file
// size limit, a directory or device named as output) never leaves a partial PNG.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace isoparm::ui {

// rgba: width * height * 4 bytes, first row at the top. `path` "-" is standard output.
// Returns "" or the reason it failed (naming the file and the system's reason).
std::string write_png(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba);

// The PNG file's bytes for rgba (width * height * 4 bytes, checked by the caller); nothing
// when memory ran out.
std::optional<std::string> encode_png(int width, int height, const std::vector<std::uint8_t>& rgba);

} // namespace isoparm::ui
