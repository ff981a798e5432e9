// Trimmed tessellation against the untrimmed grid tessellator, in triangles per second: the same
// bicubic NURBS surface and grid, trimmed by a disc with two holes and by a gear (a 48-tooth
// outer polygon with eight round holes); "first" builds the triangulation and evaluates it,
// "again" evaluates a built one (what a drag costs).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "core/geom/grid_tessellator.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/tessellate.hpp"
#include "core/geom/trim/trim.hpp"
#include "core/geom/trim/trim_validate.hpp"
#include "core/geom/trim/trimmed_tessellator.hpp"
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;

namespace {

Surface bicubic_nurbs() {
    isoparm::testing::RandomGeometry g(2024);
    Surface s = g.surface(3, 3, 32, 32, true);
    s.knots_u = clamped_uniform_knots(32, 3);
    s.knots_v = clamped_uniform_knots(32, 3);
    for (auto& w : s.weights) w = g.uniform(0.5, 2.0);
    return s;
}

Trim disc() {
    Trim t;
    t.outer = *circle_loop({0.5, 0.5}, 0.45, false);
    t.holes.push_back(*circle_loop({0.35, 0.45}, 0.12, true));
    t.holes.push_back(reversed(polygon_loop({{0.55, 0.55}, {0.75, 0.55}, {0.75, 0.75}})));
    return t;
}

Trim gear() {
    Trim t;
    std::vector<glm::dvec2> corners;
    for (int k = 0; k < 96; ++k) {
        const double a = 2 * std::numbers::pi * k / 96, r = k % 2 == 0 ? 0.48 : 0.43;
        corners.push_back({0.5 + r * std::cos(a), 0.5 + r * std::sin(a)});
    }
    t.outer = polygon_loop(corners);
    for (int k = 0; k < 8; ++k) {
        const double a = 2 * std::numbers::pi * k / 8;
        t.holes.push_back(
            *circle_loop({0.5 + 0.28 * std::cos(a), 0.5 + 0.28 * std::sin(a)}, 0.06, true));
    }
    return t;
}

const Trim& trim_of(int which) {
    static const Trim d = disc(), g = gear();
    return which == 0 ? d : g;
}

void label(benchmark::State& state, int which) {
    state.SetLabel(which == 0 ? "disc, 2 holes" : "gear, 8 holes");
}

void BM_GridUntrimmed(benchmark::State& state) {
    const Surface s = bicubic_nurbs();
    const int n = static_cast<int>(state.range(0));
    std::size_t triangles = 0;
    for (auto _ : state) {
        Mesh m = tessellate(s, n, n);
        triangles = m.triangles.size();
        benchmark::DoNotOptimize(m.positions.data());
    }
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["triangles/s"] = benchmark::Counter(
        static_cast<double>(triangles), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GridUntrimmed)->Arg(64)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);

void BM_TrimmedFirst(benchmark::State& state) {
    const Surface s = bicubic_nurbs();
    const int n = static_cast<int>(state.range(0)), which = static_cast<int>(state.range(1));
    const Trim& t = trim_of(which);
    if (!validate_trim(t, domain(s)).ok()) state.SkipWithError("invalid trim");
    std::size_t triangles = 0, cdt = 0;
    for (auto _ : state) {
        const TrimmedTessellator tess(s, t, n, n);
        Mesh m;
        tess.evaluate(s, m);
        triangles = m.triangles.size();
        cdt = tess.layout().triangles.size() - tess.layout().grid_triangles;
        benchmark::DoNotOptimize(m.positions.data());
    }
    label(state, which);
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["cdt_triangles"] = static_cast<double>(cdt);
    state.counters["triangles/s"] = benchmark::Counter(
        static_cast<double>(triangles), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TrimmedFirst)->ArgsProduct({{64, 128, 256}, {0, 1}})->Unit(benchmark::kMillisecond);

void BM_TrimmedAgain(benchmark::State& state) {
    const Surface s = bicubic_nurbs();
    const int n = static_cast<int>(state.range(0)), which = static_cast<int>(state.range(1));
    const TrimmedTessellator tess(s, trim_of(which), n, n);
    Mesh m;
    for (auto _ : state) {
        tess.evaluate(s, m);
        benchmark::DoNotOptimize(m.positions.data());
    }
    label(state, which);
    state.counters["triangles"] = static_cast<double>(m.triangles.size());
    state.counters["triangles/s"] = benchmark::Counter(
        static_cast<double>(m.triangles.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TrimmedAgain)->ArgsProduct({{64, 128, 256}, {0, 1}})->Unit(benchmark::kMillisecond);

} // namespace
