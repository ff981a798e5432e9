// Reading an animation back with FFmpeg's demuxers and decoders (tests only): how many
// frames it has, their size, and any frame as RGBA.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace isoparm::test {

struct VideoFacts {
    int frames = 0;
    int width = 0, height = 0;
    std::string codec;                    // "gif", "h264"
    double fps = 0;                       // the stream's average frame rate
    std::vector<std::uint8_t> frame_rgba; // the frame asked for (RGBA, top row first)
};

// Nothing, with `error` set, when the file cannot be opened or decoded. `keep_frame`: which
// frame to return as RGBA (-1: none).
std::optional<VideoFacts> read_video(const std::string& path, int keep_frame, std::string& error);

} // namespace isoparm::test
