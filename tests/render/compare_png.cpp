// compare_png: compares a rendered PNG with its golden image, tolerating small per-pixel
// differences (llvmpipe builds differ slightly between machines) and writing a diff image.
//
// usage: compare_png GOLDEN ACTUAL [--tolerance T] [--max-fraction F] [--diff DIFF.png]
//   A pixel differs when any channel (R, G, B) differs by more than T (0..255, default 16).
//   The images match when at most F (0..1, default 0.002) of the pixels differ; sizes must be
//   equal. `--tolerance 0 --max-fraction 0` asks for identical pixels.
// Exit status: 0 match, 1 mismatch (the diff image, if asked for, is written), 2 bad usage or
// an unreadable image.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "ui/image/png_compare.hpp"

namespace {

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

    std::string error;
    const auto golden = isoparm::ui::read_image(files[0], error);
    const auto actual = golden ? isoparm::ui::read_image(files[1], error) : std::nullopt;
    if (!golden || !actual) {
        std::fprintf(stderr, "compare_png: %s\n", error.c_str());
        return 2;
    }
    const isoparm::ui::ImageComparison c =
        isoparm::ui::compare_images(*golden, *actual, tolerance, max_fraction);
    if (!c.same_size) {
        std::fprintf(stderr, "compare_png: '%s' and '%s': %s\n", files[0], files[1],
                     c.summary.c_str());
        return 1;
    }
    std::printf("compare_png: %s\n", c.summary.c_str());
    std::fflush(stdout); // before the diff's line on stderr, so that the two stay in order
    if (!c.match && !diff_path.empty()) {
        if (const std::string problem = isoparm::ui::write_diff_image(diff_path, *golden, c);
            !problem.empty())
            std::fprintf(stderr, "compare_png: cannot write the diff image: %s\n", problem.c_str());
        else
            std::fprintf(stderr, "compare_png: diff image: %s\n", diff_path.c_str());
    }
    return c.match ? 0 : 1;
}
