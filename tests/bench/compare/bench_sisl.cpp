// isoparm against SISL (the SINTEF Spline Library) and OpenCASCADE (where found: its
// span-cached GeomAdaptor_Surface point by point, occt_grid.cpp), on the same surfaces in one
// run: grid positions, grid positions + normals, single points, knot insertion and degree
// elevation.
// Prints points per second for both, the ratio, the largest difference between their points,
// and the machine's ceiling for the grid case (the vector FMA peak in flops / flops per point
// of isoparm's scheme), per kernel path (every one this CPU runs) and for one and two threads;
// then one against two threads again, interleaved pass by pass (BM_GridThreadsInterleaved:
// on a shared machine the only comparison the drift of the machine's speed does not decide).
// ISOPARM_SIMD does not matter here: each path is chosen explicitly (GridTessellator::
// use_kernel); it does choose the path of the agreement check at the end.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <glm/geometric.hpp>
#include <sisl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/geom/evaluate.hpp"
#include "core/geom/grid_tessellator.hpp"
#include "core/geom/knots.hpp"
#include "core/geom/refine.hpp"
#include "core/geom/worker_pool.hpp"
#include "tests/bench/compare/peak_fma.hpp"
#include "tests/bench/competing_load.hpp"
#ifdef ISOPARM_BENCH_OCCT
#include "tests/bench/compare/occt_grid.hpp"
#endif
#include "tests/support/random_geometry.hpp"

using namespace isoparm::geom;

namespace {

constexpr int grid = 256;

// A rational bicubic surface with random positive weights on clamped uniform knots, in both
// libraries' forms. SISL stores homogeneous (wx, wy, wz, w) with the first direction fastest.
struct Pair {
    Surface ours;
    SISLSurf* sisl = nullptr;
    std::vector<double> knots_u, knots_v, coef; // SISL keeps pointers into these (icopy = 0)
};

Pair make_pair(int n) {
    isoparm::testing::RandomGeometry g(20261122 + n);
    Pair p;
    p.ours = g.surface(3, 3, n, n, true);
    p.ours.knots_u = p.ours.knots_v = clamped_uniform_knots(n, 3);
    for (auto& w : p.ours.weights) w = g.uniform(0.5, 2.0);
    p.knots_u = p.ours.knots_u;
    p.knots_v = p.ours.knots_v;
    p.coef.resize(static_cast<size_t>(n) * n * 4);
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double w = p.ours.weight(i, j);
            const glm::dvec3& P = p.ours.point(i, j);
            double* c = &p.coef[(static_cast<size_t>(j) * n + i) * 4];
            c[0] = P.x * w;
            c[1] = P.y * w;
            c[2] = P.z * w;
            c[3] = w;
        }
    }
    p.sisl = newSurf(n, n, 4, 4, p.knots_u.data(), p.knots_v.data(), p.coef.data(), 2, 3, 1);
    return p;
}

Pair& pair_for(int n) {
    static std::map<int, Pair> cache;
    auto it = cache.find(n);
    if (it == cache.end()) it = cache.emplace(n, make_pair(n)).first;
    return it->second;
}

const std::vector<double>& grid_params() {
    static const std::vector<double> t = uniform_params(0.0, 1.0, grid);
    return t;
}

void set_rate(benchmark::State& state, double points) {
    state.counters["points/s"] =
        benchmark::Counter(points, benchmark::Counter::kIsIterationInvariantRate);
}

// --- grid positions ---------------------------------------------------------------------

// Arguments: net size, kernel path (kernel::Path), threads.
void BM_GridPositions_isoparm(benchmark::State& state) {
    const Surface& s = pair_for(static_cast<int>(state.range(0))).ours;
    GridTessellator t(s, grid, grid);
    if (!t.use_kernel(static_cast<kernel::Path>(state.range(1))))
        return state.SkipWithError("kernel path not supported by this CPU");
    const int threads = static_cast<int>(state.range(2));
    std::vector<glm::dvec3> pos;
    std::vector<std::uint8_t> exists;
    for (auto _ : state) {
        t.evaluate_positions(s, pos, exists, threads);
        benchmark::DoNotOptimize(pos.data());
    }
    set_rate(state, grid * grid);
}

void BM_GridPositions_sisl_pointwise(benchmark::State& state) {
    SISLSurf* s = pair_for(static_cast<int>(state.range(0))).sisl;
    const auto& t = grid_params();
    std::vector<double> out(3 * grid * grid);
    for (auto _ : state) {
        int left1 = 0, left2 = 0, stat = 0;
        for (int i = 0; i < grid; ++i) {
            for (int j = 0; j < grid; ++j) {
                double par[2] = {t[i], t[j]};
                s1424(s, 0, 0, par, &left1, &left2, &out[3 * (i * grid + j)], &stat);
            }
        }
        benchmark::DoNotOptimize(out.data());
    }
    set_rate(state, grid * grid);
}

void BM_GridPositions_sisl_grid(benchmark::State& state) {
    SISLSurf* s = pair_for(static_cast<int>(state.range(0))).sisl;
    std::vector<double> t = grid_params(), out(3 * grid * grid), norm(3 * grid * grid);
    for (auto _ : state) {
        int stat = 0;
        s1506(s, 0, grid, t.data(), grid, t.data(), out.data(), norm.data(), &stat);
        benchmark::DoNotOptimize(out.data());
    }
    set_rate(state, grid * grid);
}

// --- grid positions + unit normals --------------------------------------------------------

void BM_GridNormals_isoparm(benchmark::State& state) {
    const Surface& s = pair_for(static_cast<int>(state.range(0))).ours;
    GridTessellator t(s, grid, grid);
    if (!t.use_kernel(static_cast<kernel::Path>(state.range(1))))
        return state.SkipWithError("kernel path not supported by this CPU");
    const int threads = static_cast<int>(state.range(2));
    std::vector<glm::dvec3> pos, nrm;
    std::vector<std::uint8_t> exists;
    for (auto _ : state) {
        t.evaluate_vertices(s, pos, nrm, exists, threads);
        benchmark::DoNotOptimize(nrm.data());
    }
    set_rate(state, grid * grid);
}

void normalize3(double* n) {
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0)
        for (int c = 0; c < 3; ++c) n[c] /= len;
}

void BM_GridNormals_sisl_pointwise(benchmark::State& state) {
    SISLSurf* s = pair_for(static_cast<int>(state.range(0))).sisl;
    const auto& t = grid_params();
    std::vector<double> der(9), nrm(3 * grid * grid), pos(3 * grid * grid);
    for (auto _ : state) {
        int left1 = 0, left2 = 0, stat = 0;
        for (int i = 0; i < grid; ++i) {
            for (int j = 0; j < grid; ++j) {
                double par[2] = {t[i], t[j]};
                double* n = &nrm[3 * (i * grid + j)];
                s1421(s, 1, par, &left1, &left2, der.data(), n, &stat);
                std::copy(der.begin(), der.begin() + 3, &pos[3 * (i * grid + j)]);
                normalize3(n);
            }
        }
        benchmark::DoNotOptimize(nrm.data());
    }
    set_rate(state, grid * grid);
}

void BM_GridNormals_sisl_grid(benchmark::State& state) {
    SISLSurf* s = pair_for(static_cast<int>(state.range(0))).sisl;
    std::vector<double> t = grid_params(), der(9 * grid * grid), nrm(3 * grid * grid);
    for (auto _ : state) {
        int stat = 0;
        s1506(s, 1, grid, t.data(), grid, t.data(), der.data(), nrm.data(), &stat);
        for (int k = 0; k < grid * grid; ++k) normalize3(&nrm[3 * k]);
        benchmark::DoNotOptimize(nrm.data());
    }
    set_rate(state, grid * grid);
}

#ifdef ISOPARM_BENCH_OCCT
const isoparm::bench::OcctGrid& occt_for(int n) {
    static std::map<int, std::unique_ptr<isoparm::bench::OcctGrid>> cache;
    auto& g = cache[n];
    if (!g) g = std::make_unique<isoparm::bench::OcctGrid>(pair_for(n).ours);
    return *g;
}

void BM_GridPositions_occt(benchmark::State& state) {
    const auto& g = occt_for(static_cast<int>(state.range(0)));
    std::vector<double> out(3 * grid * grid);
    for (auto _ : state) {
        g.positions(grid_params(), out.data());
        benchmark::DoNotOptimize(out.data());
    }
    set_rate(state, grid * grid);
}
BENCHMARK(BM_GridPositions_occt)->Arg(8)->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond);

void BM_GridNormals_occt(benchmark::State& state) {
    const auto& g = occt_for(static_cast<int>(state.range(0)));
    std::vector<double> pos(3 * grid * grid), nrm(3 * grid * grid);
    for (auto _ : state) {
        g.normals(grid_params(), pos.data(), nrm.data());
        benchmark::DoNotOptimize(nrm.data());
    }
    set_rate(state, grid * grid);
}
BENCHMARK(BM_GridNormals_occt)->Arg(8)->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond);
#endif

// --- one against two threads, interleaved -------------------------------------------------

// The same grid with one thread and with two, call after call: on a shared (virtual) machine
// the speed of a core drifts by half over tenths of a second, more than two threads gain, so
// runs of one case after the other can order them either way; calls a millisecond apart see
// the same machine. Each iteration times, in turn: one thread; two threads with the helper
// asleep (it has not run for longer than WorkerPool::spin_time: what a frame after idle time
// pays, wake-up included); two threads again at once (the helper still spinning: back-to-back
// passes). Before each of the first two the caller waits until the helper sleeps, spinning
// itself (a sleeping caller would start its pass on a halted virtual CPU, a handicap the
// other cases do not have), so no spinning helper runs beside the one-thread pass either.
// Counters: the medians of each (microseconds) and the speed-ups of the medians. Arguments:
// net size, kernel path, 0 positions / 1 positions + normals.
// A 256 x 256 grid of one of the nets through one kernel path, timed pass by pass.
class TimedGrid {
public:
    TimedGrid(int n, kernel::Path path, bool normals)
        : s_(pair_for(n).ours), t_(s_, grid, grid), normals_(normals) {
        supported_ = t_.use_kernel(path);
    }
    bool supported() const { return supported_; }
    // Seconds of wall time for one pass with `threads`.
    double pass(int threads) {
        using Clock = std::chrono::steady_clock;
        const auto start = Clock::now();
        if (normals_)
            t_.evaluate_vertices(s_, pos_, nrm_, exists_, threads);
        else
            t_.evaluate_positions(s_, pos_, exists_, threads);
        benchmark::DoNotOptimize(pos_.data());
        return std::chrono::duration<double>(Clock::now() - start).count();
    }

private:
    const Surface& s_;
    GridTessellator t_;
    bool normals_, supported_ = false;
    std::vector<glm::dvec3> pos_, nrm_;
    std::vector<std::uint8_t> exists_;
};

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}
double mean(const std::vector<double>& v) {
    double sum = 0;
    for (double x : v) sum += x;
    return v.empty() ? 0 : sum / static_cast<double>(v.size());
}

void BM_GridThreadsInterleaved_isoparm(benchmark::State& state) {
    using Clock = std::chrono::steady_clock;
    TimedGrid g(static_cast<int>(state.range(0)), static_cast<kernel::Path>(state.range(1)),
                state.range(2) != 0);
    if (!g.supported()) return state.SkipWithError("kernel path not supported by this CPU");
    const auto let_helper_sleep = [] {
        const auto end = Clock::now() + 2 * WorkerPool::spin_time;
        while (Clock::now() < end) {
        }
    };
    std::vector<double> one, asleep, spinning;
    for (auto _ : state) {
        let_helper_sleep();
        one.push_back(g.pass(1));
        let_helper_sleep();
        asleep.push_back(g.pass(2));
        spinning.push_back(g.pass(2));
        state.SetIterationTime(one.back() + asleep.back() + spinning.back());
    }
    const double t1 = median(one), t2 = median(asleep), t2s = median(spinning);
    state.counters["1T_us"] = 1e6 * t1;
    state.counters["2T_asleep_us"] = 1e6 * t2;
    state.counters["2T_spinning_us"] = 1e6 * t2s;
    state.counters["speedup_asleep"] = t1 / t2;
    state.counters["speedup_spinning"] = t1 / t2s;
}

// AVX2 against AVX-512 on one thread, pass after pass (the paths' rows above run seconds
// apart, and on a shared machine the speed of a core drifts by more than the paths differ).
// Counters: the medians of each (microseconds) and the ratio of the medians (AVX2 time over
// AVX-512 time: above 1, AVX-512 is faster). Arguments: net size, 0 positions / 1 normals.
void BM_GridPathsInterleaved_isoparm(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const bool normals = state.range(1) != 0;
    TimedGrid avx2(n, kernel::Path::avx2, normals), avx512(n, kernel::Path::avx512, normals);
    if (!avx2.supported() || !avx512.supported())
        return state.SkipWithError("this CPU lacks AVX2 or AVX-512");
    std::vector<double> a, b;
    for (auto _ : state) {
        a.push_back(avx2.pass(1));
        b.push_back(avx512.pass(1));
        state.SetIterationTime(a.back() + b.back());
    }
    state.counters["avx2_us"] = 1e6 * median(a);
    state.counters["avx512_us"] = 1e6 * median(b);
    state.counters["avx512_speedup"] = median(a) / median(b);
}

// One against two threads while other processes compete for every core: as many busy-spinning
// processes as this process has cores (tests/bench/competing_load.hpp), started before the
// first pass and stopped after the last. One- and two-thread passes alternate. Counters: the
// medians and the means (which hold the rare slow pass: a helper descheduled inside a task)
// of each, in microseconds, and the speed-ups of both: the pool's aim (dynamic handout, the
// contention guard) is that two threads never lose to one here, a speed-up of at least 1.
// Arguments: net size, kernel path, 0 positions / 1 positions + normals.
void BM_GridThreadsContended_isoparm(benchmark::State& state) {
    TimedGrid g(static_cast<int>(state.range(0)), static_cast<kernel::Path>(state.range(1)),
                state.range(2) != 0);
    if (!g.supported()) return state.SkipWithError("kernel path not supported by this CPU");
    std::vector<double> one, two;
    {
        const isoparm::bench::CompetingLoad load(isoparm::bench::available_cores());
        state.counters["competitors"] = load.running();
        for (auto _ : state) {
            one.push_back(g.pass(1));
            two.push_back(g.pass(2));
            state.SetIterationTime(one.back() + two.back());
        }
    }
    // The guard's verdict outlives the load by up to WorkerPool::solo_max: wait it out, so
    // that the benchmarks after this one find the pool as a quiet machine leaves it.
    while (WorkerPool::shared().solo()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const double t1 = median(one), t2 = median(two);
    state.counters["1T_us"] = 1e6 * t1;
    state.counters["2T_us"] = 1e6 * t2;
    state.counters["speedup"] = t1 / t2;
    state.counters["1T_mean_us"] = 1e6 * mean(one);
    state.counters["2T_mean_us"] = 1e6 * mean(two);
    state.counters["speedup_mean"] = mean(one) / mean(two);
}

// --- single points at random parameters ------------------------------------------------

std::vector<double> random_params() {
    isoparm::testing::RandomGeometry g(7);
    std::vector<double> p(2 * 4096);
    for (double& x : p) x = g.uniform(0.0, 1.0);
    return p;
}

void BM_SinglePoint_isoparm(benchmark::State& state) {
    const Surface& s = pair_for(32).ours;
    const auto params = random_params();
    size_t k = 0;
    for (auto _ : state) {
        const double* p = &params[2 * (k++ & 4095)];
        benchmark::DoNotOptimize(surface_point(s, p[0], p[1]));
    }
    set_rate(state, 1);
}

void BM_SinglePoint_sisl(benchmark::State& state) {
    SISLSurf* s = pair_for(32).sisl;
    const auto params = random_params();
    size_t k = 0;
    double out[3];
    for (auto _ : state) {
        double* p = const_cast<double*>(&params[2 * (k++ & 4095)]);
        int left1 = 0, left2 = 0, stat = 0;
        s1424(s, 0, 0, p, &left1, &left2, out, &stat);
        benchmark::DoNotOptimize(out);
    }
    set_rate(state, 1);
}

// --- refinement on the 32 x 32 net ---------------------------------------------------------

void BM_InsertKnot_isoparm(benchmark::State& state) {
    const Surface& s = pair_for(32).ours;
    for (auto _ : state) benchmark::DoNotOptimize(insert_knot(s, Dir::u, 0.51, 1));
}

void BM_InsertKnot_sisl(benchmark::State& state) {
    SISLSurf* s = pair_for(32).sisl;
    double knot = 0.51;
    for (auto _ : state) {
        SISLSurf* r = nullptr;
        int stat = 0;
        s1025(s, &knot, 1, nullptr, 0, &r, &stat);
        benchmark::DoNotOptimize(r);
        if (r) freeSurf(r);
    }
}

void BM_ElevateDegree_isoparm(benchmark::State& state) {
    const Surface& s = pair_for(32).ours;
    for (auto _ : state) benchmark::DoNotOptimize(elevate_degree(s, Dir::u, 1));
}

void BM_ElevateDegree_sisl(benchmark::State& state) {
    SISLSurf* s = pair_for(32).sisl;
    for (auto _ : state) {
        SISLSurf* r = nullptr;
        int stat = 0;
        s1387(s, 5, 4, &r, &stat);
        benchmark::DoNotOptimize(r);
        if (r && r != s) freeSurf(r);
    }
}

// --- the ceiling ---------------------------------------------------------------------------

// Argument: register width in doubles (4: AVX2+FMA, 8: AVX-512F).
void BM_PeakFma(benchmark::State& state) {
    const int width = static_cast<int>(state.range(0));
    if (!isoparm::bench::peak_fma_supported(width))
        return state.SkipWithError("this CPU lacks the instructions of this width");
    double sink = 0;
    std::uint64_t fmas = 0;
    for (auto _ : state) fmas += isoparm::bench::peak_fma_kernel(width, 1 << 20, &sink);
    benchmark::DoNotOptimize(sink);
    state.counters["FMA/s"] =
        benchmark::Counter(static_cast<double>(fmas), benchmark::Counter::kIsRate);
}

// The divider's ceiling. Arguments: register width in doubles, 0 c / x or 1 c / sqrt(x).
void BM_PeakDivide(benchmark::State& state) {
    const int width = static_cast<int>(state.range(0));
    if (!isoparm::bench::peak_fma_supported(width))
        return state.SkipWithError("this CPU lacks the instructions of this width");
    double sink = 0;
    std::uint64_t divisions = 0;
    for (auto _ : state)
        divisions += isoparm::bench::peak_divide_kernel(width, state.range(1) != 0, 1 << 16, &sink);
    benchmark::DoNotOptimize(sink);
    state.counters["div/s"] =
        benchmark::Counter(static_cast<double>(divisions), benchmark::Counter::kIsRate);
}

// One core's store bandwidth into a buffer of a grid's positions (grid x grid x 3 doubles), the
// memory roof of the positions kernel: points/s is bytes/s over the 25 bytes a point costs it
// (24 of position, 1 of status). Argument: store width in doubles.
void BM_PeakStore(benchmark::State& state) {
    const int width = static_cast<int>(state.range(0));
    if (!isoparm::bench::peak_fma_supported(width))
        return state.SkipWithError("this CPU lacks the instructions of this width");
    const std::size_t doubles = static_cast<std::size_t>(grid) * grid * 3;
    auto* buffer = static_cast<double*>(std::aligned_alloc(64, doubles * sizeof(double)));
    std::uint64_t bytes = 0;
    for (auto _ : state) {
        bytes += isoparm::bench::peak_store_kernel(width, buffer, doubles, 1);
        benchmark::DoNotOptimize(buffer);
        benchmark::ClobberMemory();
    }
    std::free(buffer);
    state.counters["bytes/s"] =
        benchmark::Counter(static_cast<double>(bytes), benchmark::Counter::kIsRate);
    state.counters["points/s"] =
        benchmark::Counter(static_cast<double>(bytes) / 25.0, benchmark::Counter::kIsRate);
}

constexpr kernel::Path paths[] = {kernel::Path::baseline, kernel::Path::avx2, kernel::Path::avx512};

std::string grid_name(const std::string& kind, int n, kernel::Path path, int threads) {
    return "BM_Grid" + kind + "_isoparm/" + std::to_string(n) + "/" +
           std::to_string(static_cast<int>(path)) + "/" + std::to_string(threads) +
           (threads > 1 ? "/real_time" : "");
}

void register_grid_benchmarks() {
    for (int width : {4, 8}) benchmark::RegisterBenchmark("BM_PeakFma", BM_PeakFma)->Arg(width);
    for (int width : {4, 8})
        for (int with_sqrt : {0, 1})
            benchmark::RegisterBenchmark("BM_PeakDivide", BM_PeakDivide)->Args({width, with_sqrt});
    for (int width : {4, 8}) benchmark::RegisterBenchmark("BM_PeakStore", BM_PeakStore)->Arg(width);
    for (auto fn : {BM_GridPositions_isoparm, BM_GridNormals_isoparm}) {
        const char* name =
            fn == BM_GridPositions_isoparm ? "BM_GridPositions_isoparm" : "BM_GridNormals_isoparm";
        for (int n : {8, 32, 128})
            for (kernel::Path path : paths) {
                if (!kernel::supported(path)) continue; // not measurable on this CPU
                for (int threads : {1, 2}) {
                    auto* b = benchmark::RegisterBenchmark(name, fn)
                                  ->Args({n, static_cast<int>(path), threads})
                                  ->Unit(benchmark::kMillisecond);
                    // Threads need wall time; one thread is timed like SISL, in CPU time,
                    // which other work on a shared machine disturbs less.
                    if (threads > 1) b->UseRealTime();
                }
            }
    }
    for (int n : {8, 32, 128})
        for (kernel::Path path : paths)
            for (int normals : {0, 1})
                if (kernel::supported(path))
                    benchmark::RegisterBenchmark("BM_GridThreadsInterleaved_isoparm",
                                                 BM_GridThreadsInterleaved_isoparm)
                        ->Args({n, static_cast<int>(path), normals})
                        ->UseManualTime()
                        ->Unit(benchmark::kMillisecond);
    for (int n : {8, 32, 128})
        for (int normals : {0, 1})
            benchmark::RegisterBenchmark("BM_GridPathsInterleaved_isoparm",
                                         BM_GridPathsInterleaved_isoparm)
                ->Args({n, normals})
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
    // Under load only the path the dispatch chooses (the one users get), for the nets that
    // matter; a second of passes each, so that several of the guard's retries fall inside.
    for (int n : {32, 128})
        for (int normals : {0, 1})
            benchmark::RegisterBenchmark("BM_GridThreadsContended_isoparm",
                                         BM_GridThreadsContended_isoparm)
                ->Args({n, static_cast<int>(kernel::active_path()), normals})
                ->UseManualTime()
                ->MinTime(1.0)
                ->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_GridPositions_sisl_pointwise)
    ->Arg(8)
    ->Arg(32)
    ->Arg(128)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridPositions_sisl_grid)->Arg(8)->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridNormals_sisl_pointwise)->Arg(8)->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GridNormals_sisl_grid)->Arg(8)->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SinglePoint_isoparm);
BENCHMARK(BM_SinglePoint_sisl);
BENCHMARK(BM_InsertKnot_isoparm)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_InsertKnot_sisl)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ElevateDegree_isoparm)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ElevateDegree_sisl)->Unit(benchmark::kMicrosecond);

// Collects the (median, when repeated) CPU time per benchmark for the summary.
class Collector : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> seconds; // per iteration
    std::map<std::string, double> counters;
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& r : runs) {
            if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
            std::string name = r.run_name.str();
            const double t =
                r.real_accumulated_time / std::max<double>(1, static_cast<double>(r.iterations));
            const double cpu =
                r.cpu_accumulated_time / std::max<double>(1, static_cast<double>(r.iterations));
            // Cases with threads run with UseRealTime; the others on one thread, in CPU time.
            seconds[name] = name.find("real_time") != std::string::npos ? t : cpu;
            for (const auto& [k, c] : r.counters) counters[name + ":" + k] = c.value;
        }
    }
};

// The largest distance between the two libraries' grid points and unit normals.
void print_agreement(int n) {
    Pair& p = pair_for(n);
    const GridTessellator t(p.ours, grid, grid);
    std::vector<glm::dvec3> pos, nrm;
    std::vector<std::uint8_t> exists;
    t.evaluate_vertices(p.ours, pos, nrm, exists, 1);
    const auto& u = grid_params();
    double dp = 0, dn = 0, scale = 0;
    int left1 = 0, left2 = 0, stat = 0;
    for (int i = 0; i < grid; ++i) {
        for (int j = 0; j < grid; ++j) {
            double par[2] = {u[i], u[j]}, der[9], n3[3];
            s1421(p.sisl, 1, par, &left1, &left2, der, n3, &stat);
            normalize3(n3);
            const glm::dvec3 a = pos[i * grid + j], b{der[0], der[1], der[2]};
            dp = std::max(dp, glm::length(a - b));
            scale = std::max(scale, glm::length(b));
            dn = std::max(dn, glm::length(nrm[i * grid + j] - glm::dvec3(n3[0], n3[1], n3[2])));
        }
    }
    std::printf(
        "  %3dx%-3d  max |point difference| %.3g (net size %.3g), max |normal difference| %.3g\n",
        n, n, dp, scale, dn);
#ifdef ISOPARM_BENCH_OCCT
    std::vector<double> op(3 * grid * grid), on(3 * grid * grid);
    occt_for(n).normals(u, op.data(), on.data());
    double ep = 0, en = 0;
    for (int k = 0; k < grid * grid; ++k) {
        ep =
            std::max(ep, glm::length(pos[k] - glm::dvec3(op[3 * k], op[3 * k + 1], op[3 * k + 2])));
        en =
            std::max(en, glm::length(nrm[k] - glm::dvec3(on[3 * k], on[3 * k + 1], on[3 * k + 2])));
    }
    std::printf("  %3dx%-3d  against OCCT: max |point difference| %.3g, max |normal difference| "
                "%.3g\n",
                n, n, ep, en);
#endif
}

} // namespace

int main(int argc, char** argv) {
    std::vector<char*> args(argv, argv + argc);
    std::string reps = "--benchmark_repetitions=3", agg = "--benchmark_report_aggregates_only=true",
                mintime = "--benchmark_min_time=0.2";
    bool has_reps = false, has_min = false;
    for (int k = 1; k < argc; ++k) {
        has_reps |= std::string(argv[k]).rfind("--benchmark_repetitions", 0) == 0;
        has_min |= std::string(argv[k]).rfind("--benchmark_min_time", 0) == 0;
    }
    if (!has_reps) {
        args.push_back(reps.data());
        args.push_back(agg.data());
    }
    if (!has_min) args.push_back(mintime.data());
    int count = static_cast<int>(args.size());
    benchmark::Initialize(&count, args.data());
    register_grid_benchmarks();
    Collector collector;
    benchmark::RunSpecifiedBenchmarks(&collector);

    auto rate = [&](const std::string& name) {
        auto it = collector.seconds.find(name);
        return it == collector.seconds.end() || it->second <= 0 ? 0.0 : 1.0 / it->second;
    };
    const double peak4 = 2 * collector.counters["BM_PeakFma/4:FMA/s"],
                 peak8 = 2 * collector.counters["BM_PeakFma/8:FMA/s"];
    std::printf("\nCeiling (one core, double precision): AVX2 FMA peak %.3g GFLOP/s, AVX-512 "
                "%s\n",
                peak4 * 1e-9,
                peak8 > 0 ? (std::to_string(peak8 * 1e-9) + " GFLOP/s").c_str()
                          : "not measurable (this CPU lacks AVX-512)");
    // The divider's ceiling in points per second: a point takes one division 1 / w, and with
    // normals also 1 / sqrt(|n|^2) (the kernel, grid_kernel.inl). Correctly rounded (the FMA
    // paths give the same bits), so no FMA can take the divider's place.
    const auto divider_ceiling = [&](int width, bool normals) {
        const std::string w = std::to_string(width);
        const double div = collector.counters["BM_PeakDivide/" + w + "/0:div/s"],
                     sqrt_div = collector.counters["BM_PeakDivide/" + w + "/1:div/s"];
        if (div <= 0 || sqrt_div <= 0) return 0.0;
        return normals ? 1 / (1 / div + 1 / sqrt_div) : div;
    };
    std::printf("Divider (one core): 1/x %.3g and 1/sqrt(x) %.3g per second in AVX2 registers, "
                "%.3g and %.3g in AVX-512\n",
                collector.counters["BM_PeakDivide/4/0:div/s"],
                collector.counters["BM_PeakDivide/4/1:div/s"],
                collector.counters["BM_PeakDivide/8/0:div/s"],
                collector.counters["BM_PeakDivide/8/1:div/s"]);
    std::printf("\nSummary (medians; points per second = %d x %d grid points / time per grid; "
                "kernel chosen here: %s)\n",
                grid, grid, kernel::name(kernel::active_path()));
    std::printf("  %-9s %-10s %-14s %11s %11s %11s %11s %8s %8s %8s %9s %8s %7s\n", "net", "case",
                "path/threads", "isoparm", "SISL s1506", "SISL point", "OCCT", "vs 1506",
                "vs point", "vs OCCT", "flops/pt", "of peak", "of div");
    for (int n : {8, 32, 128}) {
        const Surface& s = pair_for(n).ours;
        for (const char* kind : {"Positions", "Normals"}) {
            const bool normals = kind[0] == 'N';
            const std::string suffix = "/" + std::to_string(n);
            const double s1506 =
                grid * grid * rate("BM_Grid" + std::string(kind) + "_sisl_grid" + suffix);
            const double point =
                grid * grid * rate("BM_Grid" + std::string(kind) + "_sisl_pointwise" + suffix);
            const double occt =
                grid * grid * rate("BM_Grid" + std::string(kind) + "_occt" + suffix);
            const auto ratio = [](double a, double b) { return b > 0 ? a / b : 0.0; };
            for (kernel::Path path : paths) {
                if (!kernel::supported(path)) {
                    std::printf("  %3dx%-5d %-10s %-14s %11s\n", n, n, kind,
                                (std::string(kernel::name(path)) + "/-").c_str(),
                                "not measurable here");
                    continue;
                }
                // Flops per point of this scheme (grid_kernel.hpp), an FMA counted as two as in
                // the peak: step 2 is 4 (p + 1) multiply-adds per homogeneous value (3 values
                // with derivatives); step 1, nc per value (nc: the path's band width) for each
                // of n control rows, is shared by the grid's rows; then the quotient (4 flops)
                // or the quotient rule, cross product and normalization (about 54 flops).
                GridTessellator tess(s, grid, grid);
                tess.use_kernel(path);
                const int p = s.degree_u, nc = tess.band_columns();
                const double fma =
                    (normals ? 12.0 : 4.0) * (p + 1) + (normals ? 8.0 : 4.0) * nc * s.n_u / grid;
                const double flops = 2 * fma + (normals ? 54 : 4);
                for (int threads : {1, 2}) {
                    const double ours = grid * grid * rate(grid_name(kind, n, path, threads));
                    if (ours == 0) continue;
                    const double peak = (path == kernel::Path::avx512 ? peak8 : peak4) * threads;
                    const double divider =
                        divider_ceiling(path == kernel::Path::avx512 ? 8 : 4, normals) * threads;
                    std::printf(
                        "  %3dx%-5d %-10s %-14s %11.4g %11.4g %11.4g %11.4g %7.1fx %7.1fx "
                        "%7.1fx %9.0f %7.1f%% %6.0f%%\n",
                        n, n, kind,
                        (std::string(kernel::name(path)) + "/" + std::to_string(threads)).c_str(),
                        ours, s1506, point, occt, ratio(ours, s1506), ratio(ours, point),
                        ratio(ours, occt), flops, peak > 0 ? 100 * ours * flops / peak : 0,
                        divider > 0 ? 100 * ours / divider : 0);
                }
            }
        }
    }
    if (kernel::supported(kernel::Path::avx512) && kernel::supported(kernel::Path::avx2)) {
        std::printf("  AVX-512 against AVX2 (this run; the dispatch takes %s):",
                    kernel::name(kernel::active_path()));
        for (int n : {8, 32, 128})
            for (const char* kind : {"Positions", "Normals"})
                for (int threads : {1, 2}) {
                    const double a = rate(grid_name(kind, n, kernel::Path::avx512, threads)),
                                 b = rate(grid_name(kind, n, kernel::Path::avx2, threads));
                    if (a > 0 && b > 0)
                        std::printf("%s %d %s/%d %.2fx",
                                    threads == 1 && kind[0] == 'P' ? "\n   " : ",", n, kind,
                                    threads, a / b);
                }
        std::printf("\n");
    }
    for (int n : {8, 32, 128})
        for (int normals : {0, 1}) {
            const std::string key = "BM_GridPathsInterleaved_isoparm/" + std::to_string(n) + "/" +
                                    std::to_string(normals) + "/manual_time:";
            const auto it = collector.counters.find(key + "avx2_us");
            if (it == collector.counters.end()) continue;
            std::printf("  %3dx%-5d %-10s AVX2 %8.1f us, AVX-512 %8.1f us: AVX-512 %.2fx "
                        "(one thread, interleaved pass by pass)\n",
                        n, n, normals ? "Normals" : "Positions", it->second,
                        collector.counters[key + "avx512_us"],
                        collector.counters[key + "avx512_speedup"]);
        }
    const double sp_ours = rate("BM_SinglePoint_isoparm"), sp_sisl = rate("BM_SinglePoint_sisl");
    if (sp_ours > 0)
        std::printf("  %-28s %14.4g %14.4g %9.1fx\n", "single point (random)", sp_ours, sp_sisl,
                    sp_sisl > 0 ? sp_ours / sp_sisl : 0);
    for (const char* op : {"InsertKnot", "ElevateDegree"}) {
        const double a = rate(std::string("BM_") + op + "_isoparm"),
                     b = rate(std::string("BM_") + op + "_sisl");
        if (a > 0)
            std::printf("  %-28s %11.1f us %11.1f us %9.1fx\n",
                        (std::string(op) + " 32x32").c_str(), 1e6 / a, b > 0 ? 1e6 / b : 0.0,
                        b > 0 ? a / b : 0);
    }
    std::printf("\nOne against two threads, interleaved (medians of passes a millisecond apart; "
                "microseconds per %d x %d grid):\n",
                grid, grid);
    std::printf("  %-9s %-10s %-9s %9s %14s %14s %9s %9s\n", "net", "case", "path", "1 thread",
                "2, helper woken", "2, spinning", "woken", "spinning");
    for (int n : {8, 32, 128})
        for (int normals : {0, 1})
            for (kernel::Path path : paths) {
                const std::string key = "BM_GridThreadsInterleaved_isoparm/" + std::to_string(n) +
                                        "/" + std::to_string(static_cast<int>(path)) + "/" +
                                        std::to_string(normals) + "/manual_time:";
                const auto it = collector.counters.find(key + "1T_us");
                if (it == collector.counters.end()) continue;
                std::printf("  %3dx%-5d %-10s %-9s %9.1f %14.1f %14.1f %8.2fx %8.2fx\n", n, n,
                            normals ? "Normals" : "Positions", kernel::name(path), it->second,
                            collector.counters[key + "2T_asleep_us"],
                            collector.counters[key + "2T_spinning_us"],
                            collector.counters[key + "speedup_asleep"],
                            collector.counters[key + "speedup_spinning"]);
            }
    std::printf(
        "\nOne against two threads under a competing load (as many busy-spinning processes as "
        "cores, alternating passes; microseconds per %d x %d grid):\n",
        grid, grid);
    std::printf("  %-9s %-10s %-9s %11s %9s %9s %11s %9s %9s %8s\n", "net", "case", "path",
                "competitors", "1T median", "2T median", "speedup", "1T mean", "2T mean",
                "speedup");
    for (int n : {32, 128})
        for (int normals : {0, 1}) {
            const kernel::Path path = kernel::active_path();
            const std::string key = "BM_GridThreadsContended_isoparm/" + std::to_string(n) + "/" +
                                    std::to_string(static_cast<int>(path)) + "/" +
                                    std::to_string(normals) + "/min_time:1.000/manual_time:";
            const auto it = collector.counters.find(key + "1T_us");
            if (it == collector.counters.end()) continue;
            std::printf("  %3dx%-5d %-10s %-9s %11.0f %9.1f %9.1f %10.2fx %9.1f %9.1f %7.2fx\n", n,
                        n, normals ? "Normals" : "Positions", kernel::name(path),
                        collector.counters[key + "competitors"], it->second,
                        collector.counters[key + "2T_us"], collector.counters[key + "speedup"],
                        collector.counters[key + "1T_mean_us"],
                        collector.counters[key + "2T_mean_us"],
                        collector.counters[key + "speedup_mean"]);
        }
    std::printf("\nAgreement with SISL (same parameters, s1421 point by point) and OCCT:\n");
    for (int n : {8, 32, 128}) print_agreement(n);
    benchmark::Shutdown();
    return 0;
}
