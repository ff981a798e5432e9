// Comparing a rendered picture with its golden image, tolerating the small per-pixel
// differences between llvmpipe builds, with a diff picture of what changed. Used by
// `isoparm script --check` and by the golden tests' compare_png.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace isoparm::ui {

struct RgbImage {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb; // 3 bytes per pixel, rows top to bottom
};

// The largest side read_image takes (what isoparm writes: 8192).
inline constexpr int max_image_side = 8192;

// The picture in `path` (any format stb_image reads) as RGB; nothing, with `error` naming
// the file and the reason, when it cannot be read. Only a regular file is read (a FIFO, a
// device or a directory is refused without waiting), and not one larger than max_image_side.
std::optional<RgbImage> read_image(const std::string& path, std::string& error);

struct ImageComparison {
    bool same_size = true;
    std::size_t pixels = 0, differing = 0;
    int largest = 0;           // the largest channel difference seen (0..255)
    std::vector<bool> differs; // per pixel, when the sizes agree
    bool match = false;
    std::string summary; // one line: how many pixels differ, by how much, and the verdict
};

// A pixel differs when one of its channels differs by more than `tolerance` (0..255); the
// pictures match when they have one size and at most `max_fraction` (0..1) of the pixels differ.
ImageComparison compare_images(const RgbImage& golden, const RgbImage& actual, double tolerance,
                               double max_fraction);

// The diff picture: the golden image dimmed to grey, differing pixels in full red. "" or why
// it could not be written.
std::string write_diff_image(const std::string& path, const RgbImage& golden,
                             const ImageComparison& comparison);

} // namespace isoparm::ui
