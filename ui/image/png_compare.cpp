// Golden-image comparison on stb_image (Debian's libstb-dev).
#include "ui/image/png_compare.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "core/json/input_file.hpp"
#include "ui/image/png_writer.hpp"

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

namespace isoparm::ui {

std::optional<RgbImage> read_image(const std::string& path, std::string& error) {
    // A regular file only (a FIFO named like a golden image would block forever; a device
    // would never end), read whole within the input cap, its size checked before decoding.
    auto bytes = json_io::read_input_file(path);
    if (!bytes) {
        error = bytes.error().message;
        return std::nullopt;
    }
    const auto* first = reinterpret_cast<const unsigned char*>(bytes->data());
    const int length = static_cast<int>(std::min<std::size_t>(bytes->size(), INT32_MAX));
    RgbImage out;
    int channels = 0;
    if (!stbi_info_from_memory(first, length, &out.width, &out.height, &channels)) {
        error = "cannot read '" + path + "': " + stbi_failure_reason();
        return std::nullopt;
    }
    if (out.width > max_image_side || out.height > max_image_side) {
        error = "cannot read '" + path + "': it is " + std::to_string(out.width) + "x" +
                std::to_string(out.height) + ", more than " + std::to_string(max_image_side) +
                " pixels on a side";
        return std::nullopt;
    }
    std::unique_ptr<unsigned char, void (*)(void*)> data(
        stbi_load_from_memory(first, length, &out.width, &out.height, &channels, 3),
        stbi_image_free);
    if (!data) {
        error = "cannot read '" + path + "': " + stbi_failure_reason();
        return std::nullopt;
    }
    out.rgb.assign(data.get(), data.get() + static_cast<std::size_t>(out.width) * out.height * 3);
    return out;
}

ImageComparison compare_images(const RgbImage& golden, const RgbImage& actual, double tolerance,
                               double max_fraction) {
    ImageComparison c;
    if (golden.width != actual.width || golden.height != actual.height) {
        c.same_size = false;
        c.summary = "the golden image is " + std::to_string(golden.width) + "x" +
                    std::to_string(golden.height) + " but the picture is " +
                    std::to_string(actual.width) + "x" + std::to_string(actual.height);
        return c;
    }
    c.pixels = static_cast<std::size_t>(golden.width) * golden.height;
    c.differs.assign(c.pixels, false);
    for (std::size_t k = 0; k < c.pixels; ++k) {
        int largest = 0;
        for (int ch = 0; ch < 3; ++ch)
            largest = std::max(largest, std::abs(golden.rgb[k * 3 + ch] - actual.rgb[k * 3 + ch]));
        c.largest = std::max(c.largest, largest);
        if (largest > tolerance) {
            c.differs[k] = true;
            ++c.differing;
        }
    }
    const double fraction =
        c.pixels ? static_cast<double>(c.differing) / static_cast<double>(c.pixels) : 0;
    c.match = fraction <= max_fraction;
    char line[256];
    std::snprintf(line, sizeof line,
                  "%zu of %zu pixels (%.4f%%) differ by more than %g (largest difference %d); "
                  "allowed %.4f%%: %s",
                  c.differing, c.pixels, 100 * fraction, tolerance, c.largest, 100 * max_fraction,
                  c.match ? "match" : "MISMATCH");
    c.summary = line;
    return c;
}

std::string write_diff_image(const std::string& path, const RgbImage& golden,
                             const ImageComparison& comparison) {
    if (!comparison.same_size) return "no diff image: the sizes differ";
    std::vector<std::uint8_t> rgba(comparison.pixels * 4, 255);
    for (std::size_t k = 0; k < comparison.pixels; ++k) {
        const unsigned char* g = &golden.rgb[k * 3];
        if (comparison.differs[k]) {
            rgba[k * 4] = 255;
            rgba[k * 4 + 1] = rgba[k * 4 + 2] = 0;
        } else {
            const auto grey = static_cast<std::uint8_t>((g[0] + g[1] + g[2]) / 9);
            rgba[k * 4] = rgba[k * 4 + 1] = rgba[k * 4 + 2] = grey;
        }
    }
    return write_png(path, golden.width, golden.height, rgba);
}

} // namespace isoparm::ui
