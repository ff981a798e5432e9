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
