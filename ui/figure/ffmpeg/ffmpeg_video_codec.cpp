// The video module (libisoparm_video.so; why a module: ui/figure/video_codec.hpp): FFmpeg
// (libavformat, libavcodec, libavfilter, libswscale) behind VideoCodec. The muxer writes into
// memory through a custom AVIOContext (the MP4 muxer seeks back to finish its boxes); the
// program writes the finished bytes to disk (VideoEncoder::finish, atomically).
#include <cstdio>
#include <cstring>
#include <memory>
#include <type_traits>

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

#include "ui/figure/video_codec.hpp"

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

struct FfmpegVideoCodec final : VideoCodec {
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

    std::string add_frame(const std::vector<std::uint8_t>& rgba) override;
    std::string finish(std::string& bytes) override;
    int frames() const override { return added; }

    ~FfmpegVideoCodec() override {
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

std::string FfmpegVideoCodec::add_frame(const std::vector<std::uint8_t>& rgba) {
    const int w = settings.width, h = settings.height;
    if (rgba.size() != static_cast<std::size_t>(w) * h * 4)
        return "internal error: a frame is not " + std::to_string(w) + "x" + std::to_string(h);
    if (av_frame_make_writable(frame) < 0) return "out of memory";
    frame->pts = added;
    if (settings.format == VideoFormat::mp4) {
        const std::uint8_t* src[1] = {rgba.data()};
        const int stride[1] = {w * 4};
        sws_scale(sws, src, stride, 0, h, frame->data, frame->linesize);
        if (std::string problem = encode(frame); !problem.empty()) return problem;
    } else {
        for (int y = 0; y < h; ++y)
            std::memcpy(frame->data[0] + static_cast<std::ptrdiff_t>(y) * frame->linesize[0],
                        rgba.data() + static_cast<std::size_t>(y) * w * 4,
                        static_cast<std::size_t>(w) * 4);
        if (const int r = av_buffersrc_add_frame_flags(source, frame, AV_BUFFERSRC_FLAG_KEEP_REF);
            r < 0)
            return "making the GIF palette failed: " + av_message(r);
        if (std::string problem = drain_filters(); !problem.empty()) return problem;
    }
    ++added;
    return "";
}

std::string FfmpegVideoCodec::finish(std::string& bytes) {
    if (added == 0) return "the animation has no frames";
    if (settings.format == VideoFormat::gif) {
        if (const int r = av_buffersrc_add_frame_flags(source, nullptr, 0); r < 0)
            return "making the GIF palette failed: " + av_message(r);
        if (std::string problem = drain_filters(); !problem.empty()) return problem;
        if (!codec) return "the GIF palette filters gave no frames";
    }
    if (std::string problem = encode(nullptr); !problem.empty()) return problem;
    if (const int r = av_write_trailer(format); r < 0)
        return "cannot finish the file: " + av_message(r);
    avio_flush(io);
    bytes = std::move(memory.bytes);
    return "";
}

} // namespace isoparm::ui

// Exported (the module is built with hidden visibility): the program finds it with dlsym.
extern "C" __attribute__((visibility("default"))) isoparm::ui::VideoCodec*
isoparm_video_codec_v1(const isoparm::ui::VideoSettings& settings, std::string& error) {
    static_assert(
        std::is_same_v<decltype(&isoparm_video_codec_v1), isoparm::ui::VideoCodecFactory>);
    av_log_set_level(AV_LOG_ERROR); // x264's banner and statistics are not ours to print
    auto codec = std::make_unique<isoparm::ui::FfmpegVideoCodec>();
    codec->settings = settings;
    error = codec->start();
    return error.empty() ? codec.release() : nullptr;
}
