// Frame cost of the workstation on this machine's OpenGL (Mesa llvmpipe here: a classroom VM
// or remote desktop has no GPU): one whole workstation frame at 1440x900, the way the window
// draws it (no multisampling on a software rasteriser), for what a person does: nothing
// (a frame drawn for a hover), dragging the indicator, dragging a control point, orbiting.
// Process CPU time per frame (llvmpipe rasterises on worker threads), glFinish'ed; each
// frame's own times too, as the median and 95th percentile a drag's stutter shows in.
// coarse:0 draws every gesture frame in full (as before gesture frames existed), coarse:1 the
// way the window draws a drag or orbit on a CPU rasteriser (ui/gesture_frames.hpp: the implicit
// objects from their coarse grid's meshes, the surfaces from at most 8 samples a span): before
// and after in one run.
// ISOPARM_BENCH_FRAME_DIR=<dir> writes each case's last frame there as a PNG, to look at.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <imgui.h>
#include <string>
#include <vector>

#include "core/doc/commands.hpp"
#include "core/doc/commands_curve.hpp"
#include "core/scene/scene_io.hpp"
#include "ui/headless/egl_context.hpp"
#include "ui/headless/offscreen_target.hpp"
#include "ui/image/png_writer.hpp"
#include "ui/render/gl.hpp"
#include "ui/render/renderer.hpp"
#include "ui/view/camera.hpp"
#include "ui/view/doc_access.hpp"
#include "ui/workstation.hpp"

namespace {

using namespace isoparm;

enum class Gesture { idle, indicator, point, orbit, profile };

double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// The q-quantile (nearest rank) of the frames' times.
double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size()))) - 1;
    const std::size_t i = std::min(k, v.size() - 1);
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(i), v.end());
    return v[i];
}

// The frame in `fbo` as <dir>/<name>.png when ISOPARM_BENCH_FRAME_DIR is set.
void write_last_frame(unsigned fbo, int w, int h, const std::string& name) {
    const char* dir = std::getenv("ISOPARM_BENCH_FRAME_DIR");
    if (!dir || !*dir) return;
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    std::vector<std::uint8_t> flipped(rgba.size()); // OpenGL's rows run bottom-up
    const std::size_t row = static_cast<std::size_t>(w) * 4;
    for (int y = 0; y < h; ++y)
        std::copy_n(rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)),
                    row,
                    flipped.begin() +
                        static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(h - 1 - y)));
    for (std::size_t k = 3; k < flipped.size(); k += 4) flipped[k] = 255;
    (void)ui::write_png(std::string(dir) + "/" + name + ".png", w, h, flipped);
}

// A 64x64 bicubic NURBS surface, gently waved, with varying weights (the big-net drag case).
doc::Document nurbs_64x64() {
    doc::Document d;
    doc::Object o;
    o.name = "net64";
    geom::Surface s = doc::make_planar_grid(64, 64, 3, 3, geom::SplineType::nurbs);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            s.point(i, j).z = 0.1 * std::sin(0.4 * i) * std::cos(0.3 * j);
            s.weight(i, j) = 1.0 + 0.25 * std::sin(0.7 * i + 0.2 * j);
        }
    o.shape = doc::SurfaceObject{s};
    d.objects.push_back(o);
    d.objects.back().id = d.allocate_id();
    return d;
}

// Fig. 8's vase refined to 64x64 control points (53 knots inserted along u, 55 along v after
// the 11x9 revolution), still linked to its 11-point profile: a drag of a profile point rebuilds
// it every frame (the associative constructions' drag case). The profile is selected, as when
// its point is dragged in the curve designer.
doc::Document vase_64x64(std::uint64_t& profile, glm::dvec3& p0) {
    auto d = scene::load_scene(ISOPARM_SOURCE_DIR "/assets/scenes/fig8-revolution.json");
    if (!d) return {};
    doc::History h;
    const std::uint64_t vase = 1;
    profile = 2;
    for (int k = 0; k < 53; ++k)
        (void)h.execute(*d, doc::insert_knot(vase, geom::Dir::u, (k + 0.37) / 53));
    for (int k = 0; k < 55; ++k)
        (void)h.execute(*d, doc::insert_knot(vase, geom::Dir::v, (k + 0.37) / 55));
    d->view.selection = {profile, 5, -1};
    p0 = d->find(profile)->curve()->points[5];
    return std::move(d).value();
}

void BM_Frame1440x900(benchmark::State& state, const char* name, const char* scene,
                      Gesture gesture) {
    std::string error;
    const std::unique_ptr<ui::EglContext> egl = ui::EglContext::create(error);
    if (!egl) {
        state.SkipWithError(("no headless OpenGL: " + error).c_str());
        return;
    }
    // No scene file: the 64x64 net (or the 64x64 vase that follows its profile).
    std::uint64_t profile = 0;
    glm::dvec3 profile_p0(0);
    auto loaded = *scene
                      ? scene::load_scene(std::string(ISOPARM_SOURCE_DIR "/assets/scenes/") + scene)
                  : gesture == Gesture::profile
                      ? geom::Expected<doc::Document>(vase_64x64(profile, profile_p0))
                      : geom::Expected<doc::Document>(nurbs_64x64());
    if (loaded.ok() && gesture == Gesture::profile) {
        const doc::Object* vase = loaded->find(1);
        const geom::Surface* vs = vase ? vase->surface() : nullptr;
        if (!vs || vs->n_u != 64 || vs->n_v != 64 || !vase->construction) {
            state.SkipWithError("the 64x64 vase was not built");
            return;
        }
    }
    if (!loaded.ok()) {
        state.SkipWithError(loaded.error().message.c_str());
        return;
    }
    const int w = 1440, h = 900;
    ui::OffscreenTarget target(w, h);
    const GLuint fbo = target.fbo();
    {
        const bool software = ui::software_renderer(); // as the window chooses:
        ui::WorkstationOptions options{
            /*headless=*/true, 1.f, ui::ViewMode::workstation, software ? 0 : 4, {}};
        options.retained = software; // the frame kept, redrawn where it changed
        ui::Workstation ws(options);
        ui::AppContext& ctx = ws.context();
        ctx.doc = std::move(loaded).value();
        ui::normalize_selection(ctx.doc);
        ImGuiIO& io = ImGui::GetIO();
        io.DisplaySize = ImVec2(static_cast<float>(w), static_cast<float>(h));
        io.DeltaTime = 1.0f / 60.0f;
        io.MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
        for (int f = 0; f < 3; ++f) ws.frame(fbo); // layout, fit, first tessellation
        // A gesture (the mouse held and moving) from here on; the first gesture frame makes the
        // implicit objects' coarse meshes, once, outside the measured frames.
        ws.gesture().coarse = state.range(0) != 0;
        ws.gesture().forced = gesture != Gesture::idle;
        ws.frame(fbo);
        glFinish();
        const doc::Object* obj = nullptr;
        const geom::Surface* s = ui::current_surface(ctx.doc, &obj);
        const std::uint64_t id = obj ? obj->id : 0;
        const int pi = s ? s->n_u / 2 : 0, pj = s ? s->n_v / 2 : 0;
        const glm::dvec3 p0 = s ? s->point(pi, pj) : glm::dvec3(0);
        long n = 0;
        double redrawn = 0; // the share of the frame's pixels drawn again (the kept frame)
        std::vector<double> wall_ms, cpu_ms;
        for (auto _ : state) {
            const auto wall0 = std::chrono::steady_clock::now();
            const double cpu0 = process_cpu_ms();
            const double t = 0.02 * static_cast<double>(n++ % 40); // back and forth
            switch (gesture) {
            case Gesture::idle:
                break;
            case Gesture::indicator:
                ctx.doc.view.indicator = {0.1 + t, 0.3 + 0.5 * t};
                break;
            case Gesture::point:
                ctx.execute(doc::move_control_point(id, pi, pj, p0 + glm::dvec3(0, 0, t)));
                break;
            case Gesture::orbit:
                ui::orbit(ctx.ui.camera, 3, 1);
                break;
            case Gesture::profile:
                ctx.execute(doc::move_curve_point(profile, 5, profile_p0 + glm::dvec3(t, 0, 0)));
                break;
            }
            ws.frame(fbo);
            glFinish();
            redrawn += static_cast<double>(ws.redrawn_pixels()) / (double(w) * h);
            cpu_ms.push_back(process_cpu_ms() - cpu0);
            wall_ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall0)
                    .count());
        }
        write_last_frame(fbo, w, h, std::string(name) + "_coarse" + std::to_string(state.range(0)));
        state.SetLabel(egl->renderer_name()); // the figures are this renderer's (llvmpipe here)
        state.counters["frames_per_s"] =
            benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsRate);
        state.counters["wall_med_ms"] = quantile(wall_ms, 0.5);
        state.counters["wall_p95_ms"] = quantile(wall_ms, 0.95);
        state.counters["cpu_med_ms"] = quantile(cpu_ms, 0.5);
        state.counters["cpu_p95_ms"] = quantile(cpu_ms, 0.95);
        state.counters["redrawn_pct"] = 100 * redrawn / static_cast<double>(std::max(n, 1L));
    }
}

#define FRAME_CASE(name, scene, gesture)                                                           \
    BENCHMARK_CAPTURE(BM_Frame1440x900, name, #name, scene, gesture)                               \
        ->Unit(benchmark::kMillisecond)                                                            \
        ->MeasureProcessCPUTime()                                                                  \
        ->UseRealTime()                                                                            \
        ->MinTime(2.0)                                                                             \
        ->ArgName("coarse")                                                                        \
        ->Arg(0)                                                                                   \
        ->Arg(1)

FRAME_CASE(fig3b_idle, "fig3b-weight-5.json", Gesture::idle);
FRAME_CASE(fig3b_indicator_drag, "fig3b-weight-5.json", Gesture::indicator);
FRAME_CASE(fig3b_point_drag, "fig3b-weight-5.json", Gesture::point);
FRAME_CASE(fig3b_orbit, "fig3b-weight-5.json", Gesture::orbit);
FRAME_CASE(nurbs64_point_drag, "", Gesture::point);
// A profile point dragged while a 64x64 revolved surface follows it (rebuilt every frame).
FRAME_CASE(vase64_profile_drag, "", Gesture::profile);
FRAME_CASE(implicit_gallery_idle, "implicit-gallery.json", Gesture::idle);
// Each frame redraws some 880k triangles: the closed meshes without their hidden side.
FRAME_CASE(implicit_gallery_orbit, "implicit-gallery.json", Gesture::orbit);

} // namespace
