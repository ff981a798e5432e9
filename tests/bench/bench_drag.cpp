// Dragging a control point of a 32x32 bicubic NURBS surface: one drag step is a merged
// move_control_point command plus the re-tessellation the 3D view then does at the default
// density (the same sampling policy as the renderer). Target: under 2 ms per step.
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/doc/command.hpp"
#include "core/doc/commands.hpp"
#include "core/doc/document.hpp"
#include "core/geom/tessellate.hpp"
#include "ui/view/incremental_mesh.hpp"
#include "ui/view/tessellation_sampling.hpp"

using namespace isoparm;

namespace {

doc::Document drag_scene(int n = 32) {
    doc::Document d;
    doc::Object o;
    o.name = "big";
    geom::Surface s = doc::make_planar_grid(n, n, 3, 3, geom::SplineType::nurbs);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            s.point(i, j).z = std::sin(0.4 * i) * std::cos(0.3 * j);
            s.weight(i, j) = 1.0 + 0.5 * std::sin(0.7 * i + 0.2 * j) * 0.5;
        }
    o.shape = doc::SurfaceObject{s};
    d.objects.push_back(o);
    d.objects.back().id = d.allocate_id();
    return d;
}

// The whole step: command (merged into the drag's undo step) and re-tessellation.
void BM_DragStep32x32(benchmark::State& state) {
    doc::Document d = drag_scene();
    doc::History history;
    const std::uint64_t id = d.objects.front().id;
    const auto [su, sv] = ui::display_samples(
        std::get<doc::SurfaceObject>(d.objects.front().shape).surface, d.view.display.density);
    double t = 0;
    for (auto _ : state) {
        t += 0.01;
        history.execute(d, doc::move_control_point(id, 16, 16, {16.0, 16.0, std::sin(t)}));
        const geom::Surface& s = std::get<doc::SurfaceObject>(d.objects.front().shape).surface;
        geom::Mesh m = geom::tessellate(s, su, sv);
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.counters["samples_u"] = su;
    state.counters["samples_v"] = sv;
}
BENCHMARK(BM_DragStep32x32)->Unit(benchmark::kMillisecond);

// The re-tessellation alone, for comparison with the step.
void BM_Retessellate32x32(benchmark::State& state) {
    const doc::Document d = drag_scene();
    const geom::Surface& s = std::get<doc::SurfaceObject>(d.objects.front().shape).surface;
    const auto [su, sv] = ui::display_samples(s, d.view.display.density);
    for (auto _ : state) {
        geom::Mesh m = geom::tessellate(s, su, sv);
        benchmark::DoNotOptimize(m.positions.data());
    }
}
BENCHMARK(BM_Retessellate32x32)->Unit(benchmark::kMillisecond);

} // namespace

namespace {

// What the renderer actually does per drag step: the incremental mesh re-evaluates only the
// grid rows the moved point's basis function reaches, so the cost stays flat as the net
// grows (8x8 to 64x64) at the default density.
void BM_DragStepIncrementalByNet(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    doc::Document d = drag_scene(n);
    doc::History history;
    const std::uint64_t id = d.objects.front().id;
    const geom::Surface& s = std::get<doc::SurfaceObject>(d.objects.front().shape).surface;
    const auto [su, sv] = ui::display_samples(s, d.view.display.density);
    ui::IncrementalMesh mesh;
    mesh.update(s, su, sv);
    double t = 0;
    for (auto _ : state) {
        t += 0.01;
        history.execute(d, doc::move_control_point(id, n / 2, n / 2, {0.1, 0.2, std::sin(t)}));
        const ui::MeshChange c =
            mesh.update(std::get<doc::SurfaceObject>(d.objects.front().shape).surface, su, sv);
        benchmark::DoNotOptimize(c.vertex_count);
    }
    state.counters["vertices"] = static_cast<double>(su) * sv;
}
BENCHMARK(BM_DragStepIncrementalByNet)
    ->Arg(8)
    ->Arg(16)
    ->Arg(32)
    ->Arg(64)
    ->Unit(benchmark::kMicrosecond);

} // namespace

#include "core/doc/commands_curve.hpp"
#include "core/scene/scene_io.hpp"

namespace {

// The modeler's drag case without the frame (bench_frames' vase64_profile_drag): a point of
// Fig. 8's 11-point profile moved while the vase, refined to 64x64 and still linked to it,
// follows; the step is the command with the rebuild of its dependant (revolve, then the 108
// recorded knot insertions), then the 3D view's mesh of the rebuilt surface (every row
// changes, so the incremental mesh does all of it).
void BM_ProfileDragVase64(benchmark::State& state) {
    auto loaded = scene::load_scene(ISOPARM_SOURCE_DIR "/assets/scenes/fig8-revolution.json");
    if (!loaded) {
        state.SkipWithError(loaded.error().message.c_str());
        return;
    }
    doc::Document d = std::move(loaded).value();
    doc::History history;
    const std::uint64_t vase = 1, profile = 2;
    for (int k = 0; k < 53; ++k)
        (void)history.execute(d, doc::insert_knot(vase, geom::Dir::u, (k + 0.37) / 53));
    for (int k = 0; k < 55; ++k)
        (void)history.execute(d, doc::insert_knot(vase, geom::Dir::v, (k + 0.37) / 55));
    const geom::Surface* s0 = d.find(vase)->surface();
    if (!s0 || s0->n_u != 64 || s0->n_v != 64 || !d.find(vase)->construction) {
        state.SkipWithError("the 64x64 vase was not built");
        return;
    }
    const glm::dvec3 p0 = d.find(profile)->curve()->points[5];
    const auto [su, sv] = ui::display_samples(*s0, d.view.display.density);
    ui::IncrementalMesh mesh;
    mesh.update(*s0, su, sv);
    const bool mesh_too = state.range(0) != 0;
    long n = 0;
    for (auto _ : state) {
        const double t = 0.02 * static_cast<double>(n++ % 40);
        (void)history.execute(d, doc::move_curve_point(profile, 5, p0 + glm::dvec3(t, 0, 0)));
        if (mesh_too) {
            const ui::MeshChange c = mesh.update(*d.find(vase)->surface(), su, sv);
            benchmark::DoNotOptimize(c.vertex_count);
        }
    }
    state.counters["vertices"] = static_cast<double>(su) * sv;
}
// 0: the command and its rebuild alone; 1: with the mesh.
BENCHMARK(BM_ProfileDragVase64)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace
