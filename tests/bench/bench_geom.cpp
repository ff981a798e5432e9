// Core geometry figures: a 256x256 grid on a 32x32 bicubic NURBS surface, single points,
// knot insertion and degree elevation (the figures the first speed work reported).
#include <benchmark/benchmark.h>

#include <glm/vec2.hpp>

#include "core/geom/evaluate.hpp"
#include "core/geom/grid_tessellator.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/tessellate.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;

namespace {

Surface bicubic_nurbs(int n) {
    isoparm::testing::RandomGeometry g(2024);
    Surface s = g.surface(3, 3, n, n, true);
    s.knots_u = clamped_uniform_knots(n, 3);
    s.knots_v = clamped_uniform_knots(n, 3);
    for (auto& w : s.weights) w = g.uniform(0.5, 2.0);
    return s;
}

void BM_GridPositionsNormals256(benchmark::State& state) {
    const Surface s = bicubic_nurbs(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        Mesh m = tessellate(s, 256, 256);
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.counters["points/s"] =
        benchmark::Counter(256.0 * 256.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GridPositionsNormals256)->Arg(8)->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond);

void BM_GridPointwise256(benchmark::State& state) {
    const Surface s = bicubic_nurbs(32);
    const auto us = uniform_params(0, 1, 256);
    for (auto _ : state) {
        glm::dvec3 acc(0.0);
        for (double u : us)
            for (double v : us) acc += *surface_point(s, u, v);
        benchmark::DoNotOptimize(acc);
    }
    state.counters["points/s"] =
        benchmark::Counter(256.0 * 256.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GridPointwise256)->Unit(benchmark::kMillisecond);

void BM_SinglePoint(benchmark::State& state) {
    const Surface s = bicubic_nurbs(32);
    isoparm::testing::RandomGeometry g(1);
    std::vector<glm::dvec2> params(4096);
    for (auto& p : params) p = {g.uniform(0, 1), g.uniform(0, 1)};
    size_t k = 0;
    for (auto _ : state) {
        const glm::dvec2& p = params[k++ & 4095];
        benchmark::DoNotOptimize(surface_point(s, p.x, p.y));
    }
    state.counters["points/s"] =
        benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_SinglePoint);

void BM_InsertKnot32(benchmark::State& state) {
    const Surface s = bicubic_nurbs(32);
    for (auto _ : state) benchmark::DoNotOptimize(insert_knot(s, Dir::u, 0.51, 1));
}
BENCHMARK(BM_InsertKnot32)->Unit(benchmark::kMicrosecond);

void BM_ElevateDegree32(benchmark::State& state) {
    const Surface s = bicubic_nurbs(32);
    for (auto _ : state) benchmark::DoNotOptimize(elevate_degree(s, Dir::u, 1));
}
BENCHMARK(BM_ElevateDegree32)->Unit(benchmark::kMicrosecond);

} // namespace

namespace {

void BM_GridTwoThreads256(benchmark::State& state) {
    const Surface s = bicubic_nurbs(static_cast<int>(state.range(0)));
    const GridTessellator t(s, 256, 256);
    Mesh m;
    for (auto _ : state) {
        t.evaluate(s, m, 2);
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.counters["points/s"] =
        benchmark::Counter(256.0 * 256.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GridTwoThreads256)->Arg(32)->Unit(benchmark::kMillisecond)->UseRealTime();

// One drag step on a 32x32 bicubic NURBS at a 256x256 grid: only the support of the moved
// point is re-tessellated (compare with BM_GridPositionsNormals256/32).
void BM_DragStepLocalUpdate(benchmark::State& state) {
    Surface s = bicubic_nurbs(32);
    const GridTessellator t(s, 256, 256);
    Mesh m;
    t.evaluate(s, m);
    double z = 0;
    for (auto _ : state) {
        s.point(16, 16).z = (z += 1e-3);
        t.update_control_point(s, m, 16, 16);
        benchmark::DoNotOptimize(m.positions.data());
    }
}
BENCHMARK(BM_DragStepLocalUpdate)->Unit(benchmark::kMicrosecond);

} // namespace
