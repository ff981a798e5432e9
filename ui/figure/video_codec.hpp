// The seam between the program and its video module (libisoparm_video.so, ui/figure/ffmpeg/):
// FFmpeg and the hundred-odd libraries it brings (codecs, their own dependencies) are mapped
// and relocated only by a process that makes an animation. Linked into the program they cost
// every `isoparm` process about 80 ms of start-up (2-core Xeon, farm-bench medians:
// `isoparm --version` went from 0.122 s to 0.044 s), every `geom` call and headless render
// included. The module and the program are built together from one tree, so the interface is
// plain C++.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ui/figure/video_encoder.hpp"

namespace isoparm::ui {

// One video being encoded in memory (VideoEncoder's work, without the file). Visible from the
// module (built with hidden visibility): one type on both sides for RTTI and UBSan's checks.
class __attribute__((visibility("default"))) VideoCodec {
public:
    virtual ~VideoCodec() = default;
    // As VideoEncoder::add_frame.
    virtual std::string add_frame(const std::vector<std::uint8_t>& rgba) = 0;
    // Flushes the encoder; the whole file's bytes into `bytes`. "" or why not.
    virtual std::string finish(std::string& bytes) = 0;
    virtual int frames() const = 0;
};

// The module's one exported function: a codec for settings that check_video_settings passed,
// or nullptr with `error` saying why (no such encoder in this FFmpeg build, out of memory).
using VideoCodecFactory = VideoCodec* (*)(const VideoSettings& settings, std::string& error);
inline constexpr const char* video_codec_factory_symbol = "isoparm_video_codec_v1";
inline constexpr const char* video_module_file = "libisoparm_video.so";

} // namespace isoparm::ui
