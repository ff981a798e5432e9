// compare_png: compares a rendered PNG with its golden image, tolerating small per-pixel
// differences (llvmpipe builds differ slightly between machines) and writing a diff image.
//
// usage: compare_png GOLDEN ACTUAL [--tolerance T] [--max-fraction F] [--diff DIFF.png]
//   A pixel differs when any channel (R, G, B) differs by more than T (0..255, default 16).
//   The images match when at most F (0..1, default 0.002) of the pixels differ; sizes must be
//   equal. `--tolerance 0 --max-fraction 0` asks for identical pixels.
// Exit status: 0 match, 1 mismatch (the diff image, if asked for, is written), 2 bad usage or
// an unreadable image.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>

namespace {

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb; // 3 bytes per pixel, rows top to bottom
};

bool load(const char* path, Image& out) {
    int channels = 0;
    std::unique_ptr<unsigned char, void (*)(void*)> data(
        stbi_load(path, &out.width, &out.height, &channels, 3), stbi_image_free);
    if (!data) {
        std::fprintf(stderr, "compare_png: cannot read '%s': %s\n", path, stbi_failure_reason());
        return false;
    }
    out.rgb.assign(data.get(), data.get() + static_cast<std::size_t>(out.width) * out.height * 3);
    return true;
}

bool parse_number(const char* text, double lo, double hi, double& out) {
    char* end = nullptr;
    errno = 0;
    out = std::strtod(text, &end);
    return errno == 0 && end != text && *end == '\0' && out >= lo && out <= hi;
}

int usage(const char* why) {
    std::fprintf(stderr,
                 "compare_png: %s\nusage: compare_png GOLDEN ACTUAL [--tolerance T (0..255)] "
                 "[--max-fraction F (0..1)] [--diff DIFF.png]\n",
                 why);
    return 2;
}

// The diff picture: the golden image dimmed to grey, differing pixels in full red, so the
// places that changed stand out in an image viewer.
void write_diff(const std::string& path, const Image& golden, const std::vector<bool>& differs) {
    std::vector<unsigned char> out(golden.rgb.size());
    for (std::size_t k = 0; k < differs.size(); ++k) {
        const unsigned char* g = &golden.rgb[k * 3];
        if (differs[k]) {
            out[k * 3] = 255;
            out[k * 3 + 1] = 0;
            out[k * 3 + 2] = 0;
        } else {
            const auto grey = static_cast<unsigned char>((g[0] + g[1] + g[2]) / 9);
            out[k * 3] = out[k * 3 + 1] = out[k * 3 + 2] = grey;
        }
    }
    if (stbi_write_png(path.c_str(), golden.width, golden.height, 3, out.data(),
                       golden.width * 3) == 0)
        std::fprintf(stderr, "compare_png: cannot write the diff image '%s'\n", path.c_str());
    else
        std::fprintf(stderr, "compare_png: diff image: %s\n", path.c_str());
}

} // namespace

int main(int argc, char** argv) {
    std::vector<const char*> files;
    double tolerance = 16, max_fraction = 0.002;
    std::string diff_path;
    for (int k = 1; k < argc; ++k) {
        const std::string arg = argv[k];
        const bool has_value = k + 1 < argc;
        if (arg == "--tolerance") {
            if (!has_value || !parse_number(argv[++k], 0, 255, tolerance))
                return usage("--tolerance needs a number in 0..255");
        } else if (arg == "--max-fraction") {
            if (!has_value || !parse_number(argv[++k], 0, 1, max_fraction))
                return usage("--max-fraction needs a number in 0..1");
        } else if (arg == "--diff") {
            if (!has_value) return usage("--diff needs a file name");
            diff_path = argv[++k];
        } else if (arg.starts_with("--")) {
            return usage(("unknown option " + arg).c_str());
        } else {
            files.push_back(argv[k]);
        }
    }
    if (files.size() != 2) return usage("give exactly two images, GOLDEN and ACTUAL");

    Image golden, actual;
    if (!load(files[0], golden) || !load(files[1], actual)) return 2;
    if (golden.width != actual.width || golden.height != actual.height) {
        std::fprintf(stderr, "compare_png: '%s' is %dx%d but '%s' is %dx%d\n", files[0],
                     golden.width, golden.height, files[1], actual.width, actual.height);
        return 1;
    }

    const std::size_t pixels = static_cast<std::size_t>(golden.width) * golden.height;
    std::vector<bool> differs(pixels, false);
    std::size_t count = 0;
    int worst = 0;
    for (std::size_t k = 0; k < pixels; ++k) {
        int largest = 0;
        for (int c = 0; c < 3; ++c)
            largest = std::max(largest, std::abs(golden.rgb[k * 3 + c] - actual.rgb[k * 3 + c]));
        worst = std::max(worst, largest);
        if (largest > tolerance) {
            differs[k] = true;
            ++count;
        }
    }
    const double fraction = pixels ? static_cast<double>(count) / static_cast<double>(pixels) : 0;
    const bool match = fraction <= max_fraction;
    std::printf("compare_png: %zu of %zu pixels (%.4f%%) differ by more than %g (largest "
                "difference %d); allowed %.4f%%: %s\n",
                count, pixels, 100 * fraction, tolerance, worst, 100 * max_fraction,
                match ? "match" : "MISMATCH");
    std::fflush(stdout); // before the diff's line on stderr, so that the two stay in order
    if (!match && !diff_path.empty()) write_diff(diff_path, golden, differs);
    return match ? 0 : 1;
}
