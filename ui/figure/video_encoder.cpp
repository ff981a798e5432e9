// VideoEncoder: settings checked here, the encoding done by the video module (loaded on first
// use, ui/figure/video_codec.hpp), the file written here, atomically.
#include "ui/figure/video_encoder.hpp"

#include <dlfcn.h>
#include <mutex>

#include "core/scene/atomic_file.hpp"
#include "ui/figure/video_codec.hpp"
#include "ui/view/data_dir.hpp"

namespace isoparm::ui {

struct VideoEncoder::Impl {
    std::unique_ptr<VideoCodec> codec;
};

namespace {

// The module's factory, loaded once per process and never unloaded (FFmpeg keeps state for
// the life of the process, and a module unloaded before exit would leave LeakSanitizer's
// reports of it unnamed). nullptr, with why, when the module is missing or not ours.
VideoCodecFactory codec_factory(std::string& error) {
    static std::once_flag once;
    static VideoCodecFactory factory = nullptr;
    static std::string why;
    std::call_once(once, [] {
        const std::string path = module_file(video_module_file);
        if (path.empty()) {
            why = std::string("the video module ") + video_module_file +
                  " is not installed beside isoparm (" + module_dir_hint() + ")";
            return;
        }
        void* module = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!module) {
            const char* e = ::dlerror();
            why = "cannot load the video module " + path + ": " + (e ? e : "unknown error");
            return;
        }
        factory = reinterpret_cast<VideoCodecFactory>(::dlsym(module, video_codec_factory_symbol));
        if (!factory)
            why = "the video module " + path + " has no " + video_codec_factory_symbol +
                  " (a module of another isoparm version?)";
    });
    error = why;
    return factory;
}

} // namespace

std::string check_video_settings(const VideoSettings& s) {
    if (s.width < 16 || s.height < 16 || s.width > 4096 || s.height > 4096)
        return "the size " + std::to_string(s.width) + "x" + std::to_string(s.height) +
               " is outside 16x16 .. 4096x4096";
    if (s.format == VideoFormat::mp4 && (s.width % 2 || s.height % 2))
        return "an MP4 (H.264, 4:2:0) needs an even width and height, not " +
               std::to_string(s.width) + "x" + std::to_string(s.height);
    const int max_fps = s.format == VideoFormat::gif ? 50 : 60;
    if (s.fps < 1 || s.fps > max_fps)
        return "the frame rate " + std::to_string(s.fps) + " is outside 1.." +
               std::to_string(max_fps) +
               (s.format == VideoFormat::gif ? " (a GIF counts delays in 1/100 s)" : "");
    return "";
}

std::unique_ptr<VideoEncoder> VideoEncoder::create(const VideoSettings& settings,
                                                   std::string& error) {
    error = check_video_settings(settings);
    if (!error.empty()) return nullptr;
    const VideoCodecFactory factory = codec_factory(error);
    if (!factory) return nullptr;
    auto impl = std::make_unique<Impl>();
    impl->codec.reset(factory(settings, error));
    if (!impl->codec) return nullptr;
    return std::unique_ptr<VideoEncoder>(new VideoEncoder(std::move(impl)));
}

VideoEncoder::VideoEncoder(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VideoEncoder::~VideoEncoder() = default;

int VideoEncoder::frames() const {
    return impl_->codec->frames();
}

std::string VideoEncoder::add_frame(const std::vector<std::uint8_t>& rgba) {
    return impl_->codec->add_frame(rgba);
}

std::string VideoEncoder::finish(const std::string& path) {
    std::string bytes;
    if (std::string problem = impl_->codec->finish(bytes); !problem.empty()) return problem;
    const geom::Status written = scene::write_file_atomically(path, bytes);
    return written ? std::string{} : written.error().message;
}

} // namespace isoparm::ui
