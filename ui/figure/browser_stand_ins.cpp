// The browser build's stand-ins for what needs cairo or FFmpeg, which it does not have: every
// attempt is refused with the reason, so File > Export figure (PDF, PNG) and Export animation
// say why instead of failing (docs/web.md lists what differs from the desktop).
#include "ui/figure/drawing_files.hpp"
#include "ui/figure/video_encoder.hpp"

namespace isoparm::ui {

namespace {

constexpr const char* no_cairo =
    "PDF and PNG figures are drawn by cairo, which the browser version does not have: export "
    "the figure as SVG or TikZ here (File > Export picture makes a PNG), or use the desktop "
    "program";
constexpr const char* no_ffmpeg = "the browser version has no video encoder (FFmpeg)";

} // namespace

std::optional<std::string> cairo_pdf(const Drawing&, std::string& error) {
    error = no_cairo;
    return std::nullopt;
}

std::optional<std::string> cairo_png(const Drawing&, double, std::string& error) {
    error = no_cairo;
    return std::nullopt;
}

struct VideoEncoder::Impl {};

std::string check_video_settings(const VideoSettings&) {
    return no_ffmpeg;
}

std::unique_ptr<VideoEncoder> VideoEncoder::create(const VideoSettings&, std::string& error) {
    error = no_ffmpeg;
    return nullptr;
}

VideoEncoder::VideoEncoder(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VideoEncoder::~VideoEncoder() = default;

int VideoEncoder::frames() const {
    return 0;
}

std::string VideoEncoder::add_frame(const std::vector<std::uint8_t>&) {
    return no_ffmpeg;
}

std::string VideoEncoder::finish(const std::string&) {
    return no_ffmpeg;
}

} // namespace isoparm::ui
