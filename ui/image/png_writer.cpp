// PNG output: encoded in memory by stb_image_write (Debian's libstb-dev), written to disk by
// the one atomic-write routine, so every write error is seen and no partial PNG is left.
#include "ui/image/png_writer.hpp"

#include <string_view>

#include "core/scene/atomic_file.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace isoparm::ui {

namespace {

void append_bytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
}

} // namespace

std::string write_png(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0 || rgba.size() != static_cast<std::size_t>(width) * height * 4)
        return "internal error: picture size does not match its pixels";
    std::string encoded;
    if (!stbi_write_png_to_func(append_bytes, &encoded, width, height, 4, rgba.data(), width * 4))
        return "cannot encode the PNG for '" + path + "' (out of memory)";
    const geom::Status written = scene::write_file_atomically(path, encoded);
    return written ? std::string{} : written.error().message;
}

} // namespace isoparm::ui
