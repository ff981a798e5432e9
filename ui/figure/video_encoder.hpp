// Animations as files: RGBA frames encoded by Debian's FFmpeg libraries into an animated GIF
// (one palette for the whole animation, palettegen/paletteuse) or an MP4 (H.264, libx264 in
// Debian's libavcodec), kept in memory and written by the one atomic writer at the end, so a
// failure never leaves half a video.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace isoparm::ui {

enum class VideoFormat { gif, mp4 };

struct VideoSettings {
    VideoFormat format = VideoFormat::gif;
    int width = 640, height = 400; // mp4: both even (4:2:0 chroma)
    int fps = 10;                  // 1..60; a GIF stores delays in 1/100 s
};

// "" or why the settings cannot be encoded (naming the value).
std::string check_video_settings(const VideoSettings& s);

// The format of `path` by its extension (.gif, .mp4); false when it is neither.
bool video_format_of(const std::string& path, VideoFormat& format);

class VideoEncoder {
public:
    // Nothing, with `error` saying why (settings, no encoder in this FFmpeg build).
    static std::unique_ptr<VideoEncoder> create(const VideoSettings& settings, std::string& error);
    ~VideoEncoder();
    VideoEncoder(const VideoEncoder&) = delete;
    VideoEncoder& operator=(const VideoEncoder&) = delete;

    // One frame: width * height * 4 bytes of RGBA, the first row at the top. "" or why not.
    std::string add_frame(const std::vector<std::uint8_t>& rgba);
    // Flushes the encoder and writes the file atomically ("-": standard output). "" or why not.
    std::string finish(const std::string& path);
    int frames() const;

    struct Impl;

private:
    explicit VideoEncoder(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

} // namespace isoparm::ui
