// A 100-frame animation: the Fig. 8 vase orbiting once at 640x400, every frame rendered
// headlessly (EGL, llvmpipe here) and encoded, as `isoparm animate SCENE --orbit 360 --frames
// 100` does it (the process's start and the scene's load aside). Counters: the time per frame.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <unistd.h>

#include "core/scene/scene_io.hpp"
#include "ui/headless/animation_job.hpp"
#include "ui/headless/animation_sequences.hpp"
#include "ui/headless/egl_context.hpp"

namespace {

void BM_Animation100Frames(benchmark::State& state, isoparm::ui::VideoFormat format) {
    using namespace isoparm;
    std::string error;
    const auto egl = ui::EglContext::create(error);
    auto scene = scene::load_scene(ISOPARM_SOURCE_DIR "/assets/scenes/fig8-revolution.json");
    if (!egl || !scene) {
        state.SkipWithError(egl ? "cannot load the scene" : error.c_str());
        return;
    }
    ui::Sequence seq;
    seq.orbit = 360;
    seq.frames = 100;
    const auto steps = ui::sequence_steps(seq, *scene, false, error);
    auto script =
        steps ? scene::script_from_json(
                    {{"format", scene::script_format_name}, {"version", 1}, {"steps", *steps}}, ".")
              : geom::Expected<scene::Script>(
                    geom::make_error_nopath(geom::ErrorCode::internal, error));
    if (!script) {
        state.SkipWithError(script.error().message.c_str());
        return;
    }
    script->start = *scene;
    const std::string out = "/tmp/isoparm-bench-animation-" + std::to_string(getpid()) +
                            (format == ui::VideoFormat::gif ? ".gif" : ".mp4");
    int frames = 0;
    for (auto _ : state) {
        ui::AnimationRequest req;
        req.script = *script;
        req.include_start = false;
        req.output = out;
        req.video.format = format;
        req.video.width = 640;
        req.video.height = 400;
        req.video.fps = 25;
        auto job = ui::AnimationJob::create(std::move(req), error);
        if (!job) {
            state.SkipWithError(error.c_str());
            break;
        }
        while (!job->finished())
            if (std::string problem = job->step(); !problem.empty()) {
                state.SkipWithError(problem.c_str());
                break;
            }
        frames = job->frames_done();
    }
    state.counters["frames"] = frames;
    state.counters["time_per_frame"] =
        benchmark::Counter(frames * static_cast<double>(state.iterations()),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    std::remove(out.c_str());
}

BENCHMARK_CAPTURE(BM_Animation100Frames, mp4, isoparm::ui::VideoFormat::mp4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_Animation100Frames, gif, isoparm::ui::VideoFormat::gif)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

} // namespace
