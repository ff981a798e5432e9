// The PNG encoder: what it writes decodes to exactly the pixels it was given.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stb/stb_image.h>
#include <vector>

#include "ui/image/png_writer.hpp"

namespace {

using isoparm::ui::encode_png;

std::vector<std::uint8_t> decode(const std::string& png, int& w, int& h) {
    int channels = 0;
    unsigned char* p = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                             static_cast<int>(png.size()), &w, &h, &channels, 4);
    if (!p) return {};
    std::vector<std::uint8_t> out(p, p + static_cast<std::size_t>(w) * h * 4);
    stbi_image_free(p);
    return out;
}

void expect_round_trip(int w, int h, const std::vector<std::uint8_t>& rgba) {
    const auto png = encode_png(w, h, rgba);
    ASSERT_TRUE(png);
    int dw = 0, dh = 0;
    EXPECT_EQ(decode(*png, dw, dh), rgba);
    EXPECT_EQ(dw, w);
    EXPECT_EQ(dh, h);
}

TEST(PngWriter, NoisePicturesDecodeToTheirPixels) {
    // Noise defeats every filter and match, so the stored (incompressible) paths are covered.
    std::mt19937 rng(7);
    for (const auto& [w, h] : {std::pair{1, 1}, {17, 3}, {64, 64}, {333, 77}}) {
        std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
        for (auto& b : rgba) b = static_cast<std::uint8_t>(rng());
        expect_round_trip(w, h, rgba);
    }
}

TEST(PngWriter, RenderLikePicturesDecodeToTheirPixels) {
    // Flat panels, gradients and a few edges, as in a rendered frame: long matches and
    // every filter type get used.
    const int w = 640, h = 400;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * w + x) * 4];
            const bool panel = x < 200;
            p[0] = panel ? 40 : static_cast<std::uint8_t>(x * 255 / w);
            p[1] = panel ? 44 : static_cast<std::uint8_t>(y * 255 / h);
            p[2] = ((x / 16 + y / 16) % 2) ? 200 : 60;
            p[3] = 255;
        }
    expect_round_trip(w, h, rgba);
}

} // namespace
