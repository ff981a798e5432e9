// `video_probe FILE [FRAME OUT.png]`: prints "frames W H codec fps" of an animation, read back
// with FFmpeg's decoders (the animation tests check the numbers); with FRAME and OUT.png it
// also writes that frame as a PNG to look at.
#include <cstdio>
#include <string>

#include "tests/figure/video_reader.hpp"
#include "ui/image/png_writer.hpp"

int main(int argc, char** argv) {
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: video_probe FILE [FRAME OUT.png]\n");
        return 2;
    }
    const int keep = argc == 4 ? std::stoi(argv[2]) : -1;
    std::string error;
    const auto facts = isoparm::test::read_video(argv[1], keep, error);
    if (!facts) {
        std::fprintf(stderr, "video_probe: %s\n", error.c_str());
        return 1;
    }
    std::printf("%d %d %d %s %.3f\n", facts->frames, facts->width, facts->height,
                facts->codec.c_str(), facts->fps);
    if (argc == 4) {
        if (facts->frame_rgba.empty()) {
            std::fprintf(stderr, "video_probe: no frame %d\n", keep);
            return 1;
        }
        const std::string problem =
            isoparm::ui::write_png(argv[3], facts->width, facts->height, facts->frame_rgba);
        if (!problem.empty()) {
            std::fprintf(stderr, "video_probe: %s\n", problem.c_str());
            return 1;
        }
    }
    return 0;
}
