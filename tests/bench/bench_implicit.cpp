// Benchmarks of the implicit-surface path: expression evaluation and torus polygonization.
#include <benchmark/benchmark.h>

#include <vector>

#include "core/doc/document.hpp"
#include "core/geom/implicit/polygonize.hpp"
#include "core/scene/scene_io.hpp"

namespace {

using namespace isoparm::geom;
using namespace isoparm::geom::implicit;

// R = 0.6, r = 0.25 in [-1, 1]^3, as parameters so the slider case is what is measured.
const char* const torus_text = "(x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4*R^2*(x^2 + y^2)";

Program torus() {
    return std::move(compile(torus_text, {"R", "r"})).value();
}

// Polygonize the torus on an n^3 grid; state.range(1) = threads (0 = all).
void BM_PolygonizeTorus(benchmark::State& state) {
    const Program f = torus();
    const int n = static_cast<int>(state.range(0));
    PolygonizeOptions o;
    o.lo = glm::dvec3(-1);
    o.hi = glm::dvec3(1);
    o.cell = 2.0 / n;
    o.parameters = {0.6, 0.25};
    o.threads = static_cast<int>(state.range(1));
    std::size_t triangles = 0, vertices = 0;
    for (auto _ : state) {
        auto mesh = polygonize(f, o);
        if (!mesh) {
            state.SkipWithError(mesh.error().message.c_str());
            return;
        }
        triangles = mesh->triangles.size();
        vertices = mesh->positions.size();
        benchmark::DoNotOptimize(mesh->positions.data());
    }
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["vertices"] = static_cast<double>(vertices);
    state.counters["grid_points"] = static_cast<double>((n + 1.0) * (n + 1.0) * (n + 1.0));
    state.counters["points_per_s"] = benchmark::Counter(
        (n + 1.0) * (n + 1.0) * (n + 1.0), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PolygonizeTorus)
    ->ArgNames({"n", "threads"})
    ->Args({128, 0})
    ->Args({128, 1})
    ->Args({64, 0})
    ->Args({32, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Batch evaluation along grid rows (the polygonizer's sampling loop).
void BM_TorusValuesAlongX(benchmark::State& state) {
    const Program f = torus();
    const double params[2] = {0.6, 0.25};
    std::vector<double> xs(129), out(129), scratch;
    for (int i = 0; i <= 128; ++i) xs[i] = -1 + 2.0 * i / 128;
    for (auto _ : state) {
        for (int j = 0; j <= 128; ++j)
            f.values_along_x(xs.data(), xs.size(), -1 + 2.0 * j / 128, 0.1, out.data(), params,
                             scratch);
        benchmark::DoNotOptimize(out.data());
    }
    state.counters["points_per_s"] =
        benchmark::Counter(129.0 * 129.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TorusValuesAlongX);

// One value and gradient (the vertex refinement's step).
void BM_TorusValueAndGradient(benchmark::State& state) {
    const Program f = torus();
    const double params[2] = {0.6, 0.25};
    glm::dvec3 p(0.3, 0.5, 0.1), g;
    for (auto _ : state) {
        benchmark::DoNotOptimize(f.value_and_gradient(p, g, params));
        benchmark::DoNotOptimize(g);
    }
}
BENCHMARK(BM_TorusValueAndGradient);

// The vertex refinement's evaluations, one point per call against a block of 1024 points per
// call (Program::values_and_derivatives / values_and_gradients, the polygonizer's form): the
// same bits, the dispatch paid once per 64 points.
struct RefinementPoints {
    std::vector<glm::dvec3> points, directions;
    RefinementPoints() {
        for (int i = 0; i < 1024; ++i) {
            const double s = i / 1024.0;
            points.emplace_back(-0.9 + 1.8 * s, 0.5 - s * s, 0.2 * s);
            directions.emplace_back(0.0, 0.0, 2.0 / 128);
        }
    }
};

void BM_TorusDerivativeOnePointCalls(benchmark::State& state) {
    const Program f = torus();
    const double params[2] = {0.6, 0.25};
    const RefinementPoints r;
    for (auto _ : state)
        for (std::size_t k = 0; k < r.points.size(); ++k) {
            double d = 0;
            benchmark::DoNotOptimize(
                f.value_and_derivative(r.points[k], r.directions[k], d, params));
            benchmark::DoNotOptimize(d);
        }
    state.counters["points_per_s"] = benchmark::Counter(
        static_cast<double>(r.points.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TorusDerivativeOnePointCalls);

void BM_TorusDerivativeBatch(benchmark::State& state) {
    const Program f = torus();
    const double params[2] = {0.6, 0.25};
    const RefinementPoints r;
    std::vector<double> values(r.points.size()), derivatives(r.points.size()), scratch;
    for (auto _ : state) {
        f.values_and_derivatives(r.points.data(), r.directions.data(), r.points.size(),
                                 values.data(), derivatives.data(), params, scratch);
        benchmark::DoNotOptimize(derivatives.data());
    }
    state.counters["points_per_s"] = benchmark::Counter(
        static_cast<double>(r.points.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TorusDerivativeBatch);

void BM_TorusGradientOnePointCalls(benchmark::State& state) {
    const Program f = torus();
    const double params[2] = {0.6, 0.25};
    const RefinementPoints r;
    for (auto _ : state)
        for (const glm::dvec3& p : r.points) {
            glm::dvec3 g;
            benchmark::DoNotOptimize(f.value_and_gradient(p, g, params));
            benchmark::DoNotOptimize(g);
        }
    state.counters["points_per_s"] = benchmark::Counter(
        static_cast<double>(r.points.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TorusGradientOnePointCalls);

void BM_TorusGradientBatch(benchmark::State& state) {
    const Program f = torus();
    const double params[2] = {0.6, 0.25};
    const RefinementPoints r;
    std::vector<double> values(r.points.size()), scratch;
    std::vector<glm::dvec3> gradients(r.points.size());
    for (auto _ : state) {
        f.values_and_gradients(r.points.data(), r.points.size(), values.data(), gradients.data(),
                               params, scratch);
        benchmark::DoNotOptimize(gradients.data());
    }
    state.counters["points_per_s"] = benchmark::Counter(
        static_cast<double>(r.points.size()), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_TorusGradientBatch);

// The implicit gallery (assets/scenes/implicit-gallery.json): its six surfaces polygonized at
// their own cells, one after the other, as `isoparm render` does (threads: 0 = all, 1; shared:
// repeated subexpressions computed once (1, the default) or every time (0, as before): the
// meshes are the same to the bit).
void BM_PolygonizeGallery(benchmark::State& state) {
    auto scene =
        isoparm::scene::load_scene(ISOPARM_SOURCE_DIR "/assets/scenes/implicit-gallery.json");
    if (!scene) {
        state.SkipWithError(scene.error().message.c_str());
        return;
    }
    struct Job {
        Program f;
        PolygonizeOptions o;
    };
    std::vector<Job> jobs;
    for (const auto& obj : scene->objects) {
        const isoparm::doc::ImplicitObject* im = obj.implicit();
        if (!im) continue;
        Job j;
        j.f = std::move(compile(im->expression, im->parameter_names)).value();
        j.f.share_subexpressions(state.range(1) != 0);
        j.o.parameters = im->parameter_values;
        j.o.lo = im->lo;
        j.o.hi = im->hi;
        j.o.cell = im->cell;
        j.o.threads = static_cast<int>(state.range(0));
        jobs.push_back(std::move(j));
    }
    std::size_t triangles = 0, vertices = 0;
    for (auto _ : state) {
        triangles = vertices = 0;
        for (const Job& j : jobs) {
            auto mesh = polygonize(j.f, j.o);
            if (!mesh) {
                state.SkipWithError(mesh.error().message.c_str());
                return;
            }
            triangles += mesh->triangles.size();
            vertices += mesh->positions.size();
            benchmark::DoNotOptimize(mesh->positions.data());
        }
    }
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["vertices"] = static_cast<double>(vertices);
}
BENCHMARK(BM_PolygonizeGallery)
    ->ArgNames({"threads", "shared"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({1, 0})
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

} // namespace
