// PNG output: encoded in memory by stb_image_write (Debian's libstb-dev), written to disk by
// the one atomic-write routine, so every write error is seen and no partial PNG is left.
#include "ui/image/png_writer.hpp"

#include <cstdlib>
#include <string_view>
#ifndef __EMSCRIPTEN__
#include <zlib.h>
#endif

#include "core/scene/atomic_file.hpp"

#ifndef __EMSCRIPTEN__ // the browser build has no zlib: stb's own deflate and CRC there
namespace isoparm::ui {
namespace {

// The encoding was a tenth of a whole `isoparm render`; the pixels it stores are the same
// whichever way it is done, so it is chosen for speed, measured on rendered frames
// (tests/bench/render/bench_png.cpp): stb's own deflate (hash chains at its quality 8) with
// its per-row choice among the five PNG filters took about 110 ms for a 1280x800 frame;
// zlib's deflate at level 3 on unfiltered rows takes about 15 ms and the files come out
// 10-25% smaller. Rendered frames are flat panels and exact repeats that LZ77 finds in the
// raw bytes; the filters' differences break those repeats up more than they help the
// gradients. The buffer is malloc'd because stb frees it with free().
constexpr int deflate_level = 3;

unsigned char* zlib_compress(const unsigned char* data, int size, int* out_size, int /*quality*/) {
    uLongf capacity = compressBound(static_cast<uLong>(size));
    auto* out = static_cast<unsigned char*>(std::malloc(capacity));
    if (!out) return nullptr;
    if (compress2(out, &capacity, data, static_cast<uLong>(size), deflate_level) != Z_OK) {
        std::free(out);
        return nullptr;
    }
    *out_size = static_cast<int>(capacity);
    return out;
}

// zlib's CRC is table-sliced, stb's goes a byte at a time.
unsigned int zlib_crc32(const unsigned char* data, int size) {
    return static_cast<unsigned int>(crc32(crc32(0L, Z_NULL, 0), data, static_cast<uInt>(size)));
}

} // namespace
} // namespace isoparm::ui

#define STBIW_ZLIB_COMPRESS isoparm::ui::zlib_compress
#define STBIW_CRC32 isoparm::ui::zlib_crc32
#endif
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace isoparm::ui {

namespace {

void append_bytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
}

} // namespace

std::optional<std::string> encode_png(int width, int height,
                                      const std::vector<std::uint8_t>& rgba) {
    // Filter type 0 (none) on every row; stb's setting is a global, set once (thread-safe).
    static const bool unfiltered = (stbi_write_force_png_filter = 0, true);
    (void)unfiltered;
    std::string encoded;
    if (!stbi_write_png_to_func(append_bytes, &encoded, width, height, 4, rgba.data(), width * 4))
        return std::nullopt;
    return encoded;
}

std::string write_png(const std::string& path, int width, int height,
                      const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0 || rgba.size() != static_cast<std::size_t>(width) * height * 4)
        return "internal error: picture size does not match its pixels";
    const std::optional<std::string> encoded = encode_png(width, height, rgba);
    if (!encoded) return "cannot encode the PNG for '" + path + "' (out of memory)";
    const geom::Status written = scene::write_file_atomically(path, *encoded);
    return written ? std::string{} : written.error().message;
}

} // namespace isoparm::ui
