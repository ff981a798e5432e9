#include "tests/figure/video_reader.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

namespace isoparm::test {

std::optional<VideoFacts> read_video(const std::string& path, int keep_frame, std::string& error) {
    AVFormatContext* format = nullptr;
    if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) {
        error = "cannot open " + path;
        return std::nullopt;
    }
    std::optional<VideoFacts> out;
    AVCodecContext* codec = nullptr;
    AVPacket* packet = av_packet_alloc();
    AVFrame* frame = av_frame_alloc();
    SwsContext* sws = nullptr;
    const int stream = avformat_find_stream_info(format, nullptr) >= 0
                           ? av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0)
                           : -1;
    if (stream < 0) {
        error = "no video stream in " + path;
    } else {
        const AVCodecParameters* par = format->streams[stream]->codecpar;
        const AVCodec* dec = avcodec_find_decoder(par->codec_id);
        codec = dec ? avcodec_alloc_context3(dec) : nullptr;
        if (!codec || avcodec_parameters_to_context(codec, par) < 0 ||
            avcodec_open2(codec, dec, nullptr) < 0) {
            error = "no decoder for " + path;
        } else {
            VideoFacts facts;
            facts.codec = dec->name;
            const AVRational r = format->streams[stream]->avg_frame_rate;
            facts.fps = r.den ? av_q2d(r) : 0;
            auto receive = [&] {
                while (avcodec_receive_frame(codec, frame) >= 0) {
                    facts.width = frame->width;
                    facts.height = frame->height;
                    if (facts.frames == keep_frame) {
                        sws = sws_getCachedContext(sws, frame->width, frame->height,
                                                   static_cast<AVPixelFormat>(frame->format),
                                                   frame->width, frame->height, AV_PIX_FMT_RGBA,
                                                   SWS_BILINEAR, nullptr, nullptr, nullptr);
                        facts.frame_rgba.resize(static_cast<std::size_t>(frame->width) *
                                                frame->height * 4);
                        std::uint8_t* dst[1] = {facts.frame_rgba.data()};
                        const int stride[1] = {frame->width * 4};
                        sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
                    }
                    ++facts.frames;
                    av_frame_unref(frame);
                }
            };
            while (av_read_frame(format, packet) >= 0) {
                if (packet->stream_index == stream && avcodec_send_packet(codec, packet) >= 0)
                    receive();
                av_packet_unref(packet);
            }
            avcodec_send_packet(codec, nullptr);
            receive();
            out = facts;
        }
    }
    sws_freeContext(sws);
    av_frame_free(&frame);
    av_packet_free(&packet);
    avcodec_free_context(&codec);
    avformat_close_input(&format);
    return out;
}

} // namespace isoparm::test
