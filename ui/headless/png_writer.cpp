// PNG output through stb_image_write (Debian's libstb-dev).
#include "ui/headless/png_writer.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>
#include <unistd.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace isoparm::ui {

std::string write_png(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0 || rgba.size() != static_cast<std::size_t>(width) * height * 4)
        return "internal error: picture size does not match its pixels";
    // The temporary file sits beside the target so the rename stays on one file system.
    const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
    if (!stbi_write_png(tmp.c_str(), width, height, 4, rgba.data(), width * 4)) {
        const std::string why = std::strerror(errno);
        std::remove(tmp.c_str());
        return "cannot write '" + path + "': " + why;
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        return "cannot write '" + path + "': " + ec.message();
    }
    return {};
}

} // namespace isoparm::ui
