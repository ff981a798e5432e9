// Animations encoded and read back with FFmpeg's decoders: frame count, size, codec and the
// colours of a frame.
#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>

#include "tests/figure/video_reader.hpp"
#include "ui/figure/video_encoder.hpp"

namespace isoparm::ui {
namespace {

std::string temp_path(const std::string& name) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("isoparm-video-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

// Frame k: a solid colour of its own, with a white square whose place moves.
std::vector<std::uint8_t> frame(int w, int h, int k) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
    const std::uint8_t r = static_cast<std::uint8_t>(40 * k % 256), g = 200,
                       b = static_cast<std::uint8_t>(255 - 30 * k);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * w + x) * 4];
            const bool square = x >= 4 * k && x < 4 * k + 8 && y >= 8 && y < 16;
            p[0] = square ? 255 : r;
            p[1] = square ? 255 : g;
            p[2] = square ? 255 : b;
            p[3] = 255;
        }
    return rgba;
}

void round_trip(VideoFormat format, const std::string& name, const std::string& codec) {
    VideoSettings s;
    s.format = format;
    s.width = 64;
    s.height = 48;
    s.fps = 8;
    std::string error;
    auto encoder = VideoEncoder::create(s, error);
    ASSERT_TRUE(encoder) << error;
    for (int k = 0; k < 7; ++k) ASSERT_EQ(encoder->add_frame(frame(64, 48, k)), "");
    const std::string path = temp_path(name);
    ASSERT_EQ(encoder->finish(path), "");
    const auto facts = test::read_video(path, 3, error);
    ASSERT_TRUE(facts) << error;
    EXPECT_EQ(facts->frames, 7);
    EXPECT_EQ(facts->width, 64);
    EXPECT_EQ(facts->height, 48);
    EXPECT_EQ(facts->codec, codec);
    // Frame 3's background and its white square, within what a palette or YUV 4:2:0 keeps.
    ASSERT_EQ(facts->frame_rgba.size(), 64u * 48 * 4);
    const auto at = [&](int x, int y, int c) {
        return static_cast<int>(facts->frame_rgba[(static_cast<std::size_t>(y) * 64 + x) * 4 + c]);
    };
    const std::vector<std::uint8_t> want = frame(64, 48, 3);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(at(40, 36, c), want[(36 * 64 + 40) * 4 + c], 12) << "channel " << c;
        EXPECT_NEAR(at(15, 12, c), 255, 12) << "channel " << c;
    }
    std::filesystem::remove(path);
}

TEST(VideoEncoder, GifReadsBackFrameForFrame) {
    round_trip(VideoFormat::gif, "seven.gif", "gif");
}

TEST(VideoEncoder, Mp4IsH264AndReadsBackFrameForFrame) {
    round_trip(VideoFormat::mp4, "seven.mp4", "h264");
}

TEST(VideoEncoder, RefusesWhatCannotBeEncoded) {
    VideoSettings s;
    s.format = VideoFormat::mp4;
    s.width = 65;
    s.height = 48;
    EXPECT_NE(check_video_settings(s).find("even"), std::string::npos);
    s.width = 64;
    s.fps = 0;
    EXPECT_NE(check_video_settings(s).find("frame rate 0"), std::string::npos);
    s.format = VideoFormat::gif;
    s.fps = 60;
    EXPECT_NE(check_video_settings(s).find("1/100"), std::string::npos);
    s.fps = 10;
    s.width = 8;
    EXPECT_NE(check_video_settings(s).find("8x48"), std::string::npos);
    VideoFormat f;
    EXPECT_TRUE(video_format_of("a/b.GIF", f));
    EXPECT_EQ(f, VideoFormat::gif);
    EXPECT_TRUE(video_format_of("x.mp4", f));
    EXPECT_EQ(f, VideoFormat::mp4);
    EXPECT_FALSE(video_format_of("x.webm", f));
}

TEST(VideoEncoder, NoFramesWritesNothing) {
    VideoSettings s;
    std::string error;
    auto encoder = VideoEncoder::create(s, error);
    ASSERT_TRUE(encoder) << error;
    const std::string path = temp_path("empty.gif");
    EXPECT_NE(encoder->finish(path), "");
    EXPECT_FALSE(std::filesystem::exists(path));
}

} // namespace
} // namespace isoparm::ui
