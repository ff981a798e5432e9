// Headless rendering: one scene to a 1280x800 PNG through EGL (Mesa llvmpipe here), the whole
// path `isoparm render` takes: context, scene load, two frames of the workstation, PNG write.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <unistd.h>

#include "ui/headless/headless_render.hpp"

namespace {

void BM_RenderScene1280x800(benchmark::State& state, const char* scene,
                            isoparm::ui::ViewMode view) {
    const std::string out = "/tmp/isoparm-bench-render-" + std::to_string(getpid()) + ".png";
    for (auto _ : state) {
        isoparm::ui::HeadlessRequest req;
        req.scene_path = std::string(ISOPARM_SOURCE_DIR "/assets/scenes/") + scene;
        req.output = out;
        req.view = view;
        const std::string error = isoparm::ui::render_headless(req);
        if (!error.empty()) {
            state.SkipWithError(error.c_str());
            break;
        }
    }
    std::remove(out.c_str());
}

BENCHMARK_CAPTURE(BM_RenderScene1280x800, workstation_fig3b, "fig3b-weight-5.json",
                  isoparm::ui::ViewMode::workstation)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(5);
BENCHMARK_CAPTURE(BM_RenderScene1280x800, view3d_fig8, "fig8-revolution.json",
                  isoparm::ui::ViewMode::view3d_only)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(5);

} // namespace
