// PNG encoding of a 1280x800 picture (the size `isoparm render` writes by default): the
// workstation's golden images, so the figures are real frames'.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "ui/image/png_compare.hpp"
#include "ui/image/png_writer.hpp"

namespace {

void BM_EncodePng(benchmark::State& state, const char* golden) {
    std::string error;
    const auto image = isoparm::ui::read_image(
        std::string(ISOPARM_SOURCE_DIR "/tests/render/golden/") + golden, error);
    if (!image) {
        state.SkipWithError(error.c_str());
        return;
    }
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(image->width) * image->height * 4);
    for (std::size_t p = 0; p * 3 < image->rgb.size(); ++p) {
        for (int c = 0; c < 3; ++c) rgba[p * 4 + c] = image->rgb[p * 3 + c];
        rgba[p * 4 + 3] = 255;
    }
    std::size_t bytes = 0;
    for (auto _ : state) {
        const auto png = isoparm::ui::encode_png(image->width, image->height, rgba);
        bytes = png ? png->size() : 0;
        benchmark::DoNotOptimize(bytes);
    }
    state.counters["png_bytes"] = static_cast<double>(bytes);
    state.counters["pixels"] = static_cast<double>(image->width) * image->height;
}

BENCHMARK_CAPTURE(BM_EncodePng, curve_designer, "curve-designer-workstation.png")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EncodePng, fig3b, "fig3b-weight-5-workstation.png")
    ->Unit(benchmark::kMillisecond);

} // namespace
