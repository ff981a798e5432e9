// FFmpeg (libavformat, libavcodec, libavfilter, libswscale) behind VideoEncoder. The muxer
// writes into memory through a custom AVIOContext (the MP4 muxer seeks back to finish its
// boxes), and the finished bytes go to disk through scene::write_file_atomically.
#include "ui/figure/video_encoder.hpp"

#include <algorithm>
#include <cstring>
#include <string_view>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavfilter/buffersrc.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

#include "core/scene/atomic_file.hpp"

namespace isoparm::ui {

namespace {

std::string av_message(int code) {
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

// The muxer's output: a growing byte string with a position, so MP4 can seek back.
struct MemoryOutput {
    std::string bytes;
    std::int64_t pos = 0;
};

int write_packet(void* opaque, std::uint8_t* buf, int size) {
    auto* m = static_cast<MemoryOutput*>(opaque);
    const std::size_t end = static_cast<std::size_t>(m->pos) + static_cast<std::size_t>(size);
    if (end > m->bytes.size()) m->bytes.resize(end);
    std::memcpy(m->bytes.data() + m->pos, buf, static_cast<std::size_t>(size));
    m->pos = static_cast<std::int64_t>(end);
    return size;
}

std::int64_t seek(void* opaque, std::int64_t offset, int whence) {
    auto* m = static_cast<MemoryOutput*>(opaque);
    const auto size = static_cast<std::int64_t>(m->bytes.size());
    switch (whence & ~AVSEEK_FORCE) {
    case AVSEEK_SIZE:
        return size;
    case SEEK_SET:
        m->pos = offset;
        break;
    case SEEK_CUR:
        m->pos += offset;
        break;
    case SEEK_END:
        m->pos = size + offset;
        break;
    default:
        return AVERROR(EINVAL);
    }
    if (m->pos < 0) return AVERROR(EINVAL);
    return m->pos;
}

// A GIF has one 256-colour palette: made from every frame (palettegen sees them all before
// paletteuse maps the first), ordered dithering so that still parts of the picture do not
// shimmer from frame to frame as error diffusion would make them.
constexpr const char* gif_filters = "split[a][b];[a]palettegen=stats_mode=full[p];"
                                    "[b][p]paletteuse=dither=bayer:bayer_scale=4";

} // namespace

struct VideoEncoder::Impl {
    VideoSettings settings;
    MemoryOutput memory;
    AVFormatContext* format = nullptr;
    AVIOContext* io = nullptr;
    AVCodecContext* codec = nullptr;
    AVStream* stream = nullptr;
    SwsContext* sws = nullptr;      // mp4: RGBA -> YUV 4:2:0
    AVFilterGraph* graph = nullptr; // gif: RGBA -> palette -> PAL8
    AVFilterContext* source = nullptr;
    AVFilterContext* sink = nullptr;
    AVFrame* frame = nullptr;
    AVFrame* filtered = nullptr;
    AVPacket* packet = nullptr;
    int added = 0;
    bool header_written = false;

    ~Impl() {
        av_packet_free(&packet);
        av_frame_free(&frame);
        av_frame_free(&filtered);
        avfilter_graph_free(&graph);
        sws_freeContext(sws);
        avcodec_free_context(&codec);
        if (format) avformat_free_context(format);
        if (io) {
            av_freep(&io->buffer);
            avio_context_free(&io);
        }
    }

    std::string open_codec(AVCodecID id, const char* name, AVPixelFormat pix_fmt,
                           AVDictionary** options) {
        const AVCodec* c = name ? avcodec_find_encoder_by_name(name) : nullptr;
        if (!c) c = avcodec_find_encoder(id);
        if (!c) return std::string("this FFmpeg build has no ") + avcodec_get_name(id) + " encoder";
        codec = avcodec_alloc_context3(c);
        if (!codec) return "out of memory";
        codec->width = settings.width;
        codec->height = settings.height;
        codec->time_base = AVRational{1, settings.fps};
        codec->framerate = AVRational{settings.fps, 1};
        codec->pix_fmt = pix_fmt;
        if (format->oformat->flags & AVFMT_GLOBALHEADER)
            codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        if (const int r = avcodec_open2(codec, c, options); r < 0)
            return std::string("cannot open the ") + c->name + " encoder: " + av_message(r);
        stream = avformat_new_stream(format, nullptr);
        if (!stream) return "out of memory";
        avcodec_parameters_from_context(stream->codecpar, codec);
        stream->time_base = codec->time_base;
        if (const int r = avformat_write_header(format, nullptr); r < 0)
            return "cannot start the file: " + av_message(r);
        header_written = true;
        return "";
    }

    // Sends `f` (nullptr: end) to the encoder and muxes what comes out.
    std::string encode(AVFrame* f) {
        if (const int r = avcodec_send_frame(codec, f); r < 0)
            return "encoding failed: " + av_message(r);
        while (true) {
            const int r = avcodec_receive_packet(codec, packet);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return "";
            if (r < 0) return "encoding failed: " + av_message(r);
            if (packet->duration == 0) packet->duration = 1;
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            if (const int w = av_interleaved_write_frame(format, packet); w < 0)
                return "writing a frame failed: " + av_message(w);
        }
    }

    // gif: what the filter graph has ready, through the encoder (opened with the first).
    std::string drain_filters() {
        while (true) {
            const int r = av_buffersink_get_frame(sink, filtered);
            if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return "";
            if (r < 0) return "making the GIF palette failed: " + av_message(r);
            std::string problem;
            if (!codec) problem = open_codec(AV_CODEC_ID_GIF, nullptr, AV_PIX_FMT_PAL8, nullptr);
            if (problem.empty()) problem = encode(filtered);
            av_frame_unref(filtered);
            if (!problem.empty()) return problem;
        }
    }

    std::string start() {
        const char* muxer = settings.format == VideoFormat::gif ? "gif" : "mp4";
        if (avformat_alloc_output_context2(&format, nullptr, muxer, nullptr) < 0 || !format)
            return std::string("this FFmpeg build has no ") + muxer + " muxer";
        constexpr int buffer_size = 1 << 16;
        auto* buffer = static_cast<unsigned char*>(av_malloc(buffer_size));
        io = buffer
                 ? avio_alloc_context(buffer, buffer_size, 1, &memory, nullptr, write_packet, seek)
                 : nullptr;
        if (!io) {
            av_free(buffer);
            return "out of memory";
        }
        format->pb = io;
        format->flags |= AVFMT_FLAG_CUSTOM_IO;
        frame = av_frame_alloc();
        filtered = av_frame_alloc();
        packet = av_packet_alloc();
        if (!frame || !filtered || !packet) return "out of memory";

        if (settings.format == VideoFormat::mp4) {
            AVDictionary* options = nullptr;
            // Figures are flat colours and thin lines: a low CRF keeps them sharp; "animation"
            // tunes x264 for exactly such pictures.
            av_dict_set(&options, "crf", "18", 0);
            av_dict_set(&options, "preset", "medium", 0);
            av_dict_set(&options, "tune", "animation", 0);
            std::string problem =
                open_codec(AV_CODEC_ID_H264, "libx264", AV_PIX_FMT_YUV420P, &options);
            av_dict_free(&options);
            if (!problem.empty()) return problem;
            sws = sws_getContext(settings.width, settings.height, AV_PIX_FMT_RGBA, settings.width,
                                 settings.height, AV_PIX_FMT_YUV420P,
                                 SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr,
                                 nullptr, nullptr);
            if (!sws) return "cannot convert RGBA to YUV 4:2:0";
            frame->format = AV_PIX_FMT_YUV420P;
        } else {
            graph = avfilter_graph_alloc();
            if (!graph) return "out of memory";
            char args[160];
            std::snprintf(
                args, sizeof args, "video_size=%dx%d:pix_fmt=%d:time_base=1/%d:pixel_aspect=1/1",
                settings.width, settings.height, static_cast<int>(AV_PIX_FMT_RGBA), settings.fps);
            if (avfilter_graph_create_filter(&source, avfilter_get_by_name("buffer"), "in", args,
                                             nullptr, graph) < 0 ||
                avfilter_graph_create_filter(&sink, avfilter_get_by_name("buffersink"), "out",
                                             nullptr, nullptr, graph) < 0)
                return "this FFmpeg build lacks the buffer filters";
            const AVPixelFormat pal8[] = {AV_PIX_FMT_PAL8, AV_PIX_FMT_NONE};
            av_opt_set_int_list(sink, "pix_fmts", pal8, AV_PIX_FMT_NONE, AV_OPT_SEARCH_CHILDREN);
            AVFilterInOut* outputs = avfilter_inout_alloc();
            AVFilterInOut* inputs = avfilter_inout_alloc();
            std::string problem;
            if (!outputs || !inputs) {
                problem = "out of memory";
            } else {
                outputs->name = av_strdup("in");
                outputs->filter_ctx = source;
                inputs->name = av_strdup("out");
                inputs->filter_ctx = sink;
                int r = avfilter_graph_parse_ptr(graph, gif_filters, &inputs, &outputs, nullptr);
                if (r >= 0) r = avfilter_graph_config(graph, nullptr);
                if (r < 0) problem = "cannot set up the GIF palette filters: " + av_message(r);
            }
            avfilter_inout_free(&inputs);
            avfilter_inout_free(&outputs);
            if (!problem.empty()) return problem;
            frame->format = AV_PIX_FMT_RGBA;
        }
        frame->width = settings.width;
        frame->height = settings.height;
        if (av_frame_get_buffer(frame, 0) < 0) return "out of memory";
        return "";
    }
};

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

bool video_format_of(const std::string& path, VideoFormat& format) {
    std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".gif")
        format = VideoFormat::gif;
    else if (ext == ".mp4")
        format = VideoFormat::mp4;
    else
        return false;
    return true;
}

std::unique_ptr<VideoEncoder> VideoEncoder::create(const VideoSettings& settings,
                                                   std::string& error) {
    error = check_video_settings(settings);
    if (!error.empty()) return nullptr;
    av_log_set_level(AV_LOG_ERROR); // x264's banner and statistics are not ours to print
    auto impl = std::make_unique<Impl>();
    impl->settings = settings;
    error = impl->start();
    if (!error.empty()) return nullptr;
    return std::unique_ptr<VideoEncoder>(new VideoEncoder(std::move(impl)));
}

VideoEncoder::VideoEncoder(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VideoEncoder::~VideoEncoder() = default;

int VideoEncoder::frames() const {
    return impl_->added;
}

std::string VideoEncoder::add_frame(const std::vector<std::uint8_t>& rgba) {
    Impl& m = *impl_;
    const int w = m.settings.width, h = m.settings.height;
    if (rgba.size() != static_cast<std::size_t>(w) * h * 4)
        return "internal error: a frame is not " + std::to_string(w) + "x" + std::to_string(h);
    if (av_frame_make_writable(m.frame) < 0) return "out of memory";
    m.frame->pts = m.added;
    if (m.settings.format == VideoFormat::mp4) {
        const std::uint8_t* src[1] = {rgba.data()};
        const int stride[1] = {w * 4};
        sws_scale(m.sws, src, stride, 0, h, m.frame->data, m.frame->linesize);
        if (std::string problem = m.encode(m.frame); !problem.empty()) return problem;
    } else {
        for (int y = 0; y < h; ++y)
            std::memcpy(m.frame->data[0] + static_cast<std::ptrdiff_t>(y) * m.frame->linesize[0],
                        rgba.data() + static_cast<std::size_t>(y) * w * 4,
                        static_cast<std::size_t>(w) * 4);
        if (const int r =
                av_buffersrc_add_frame_flags(m.source, m.frame, AV_BUFFERSRC_FLAG_KEEP_REF);
            r < 0)
            return "making the GIF palette failed: " + av_message(r);
        if (std::string problem = m.drain_filters(); !problem.empty()) return problem;
    }
    ++m.added;
    return "";
}

std::string VideoEncoder::finish(const std::string& path) {
    Impl& m = *impl_;
    if (m.added == 0) return "the animation has no frames";
    if (m.settings.format == VideoFormat::gif) {
        if (const int r = av_buffersrc_add_frame_flags(m.source, nullptr, 0); r < 0)
            return "making the GIF palette failed: " + av_message(r);
        if (std::string problem = m.drain_filters(); !problem.empty()) return problem;
        if (!m.codec) return "the GIF palette filters gave no frames";
    }
    if (std::string problem = m.encode(nullptr); !problem.empty()) return problem;
    if (const int r = av_write_trailer(m.format); r < 0)
        return "cannot finish the file: " + av_message(r);
    avio_flush(m.io);
    const geom::Status written = scene::write_file_atomically(path, m.memory.bytes);
    return written ? std::string{} : written.error().message;
}

} // namespace isoparm::ui
