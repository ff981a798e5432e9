// What the work budget's constants (core/doc/work_budget.hpp) claim, measured through the
// protocol's text path: each case reports "steps/s", its estimated basis steps per second of
// wall time. The budget assumes about 1e8 (so 1e9 steps is about 10 s); a machine far below
// that figure wants smaller constants. Figures are printed, never asserted.
#include <benchmark/benchmark.h>

#include <nlohmann/json.hpp>
#include <ostream>
#include <streambuf>
#include <string>

#include "core/geom/work_budget.hpp"
#include "core/protocol/protocol.hpp"
#include "tests/support/protocol_shapes.hpp"

namespace {

using isoparm::test::bicubic;
using isoparm::test::curve_of_degree;

using nlohmann::json;
using namespace isoparm;
using namespace isoparm::protocol;

// An ostream that drops everything (the answer's text is produced, not kept).
class NullBuffer : public std::streambuf {
protected:
    int overflow(int c) override { return c; }
    std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

void run(benchmark::State& state, const std::string& request, double steps) {
    NullBuffer sink;
    std::ostream out(&sink), err(&sink);
    for (auto _ : state) benchmark::DoNotOptimize(run_protocol_text(request, out, err));
    state.counters["steps/s"] =
        benchmark::Counter(steps, benchmark::Counter::kIsIterationInvariantRate);
}

// The case: (p + 1)^2 steps per parameter dominate.
void BM_BudgetEvaluateDegree4095Curve(benchmark::State& state) {
    const int count = 4;
    json params = json::array();
    for (int k = 0; k < count; ++k) params.push_back((k + 0.5) / count);
    const json request = {{"op", "evaluate"}, {"curve", curve_of_degree(4095)}, {"params", params}};
    run(state, request.dump(), geom::estimate_curve_evaluation(count, 4095, 0).steps);
}
BENCHMARK(BM_BudgetEvaluateDegree4095Curve)->Unit(benchmark::kMillisecond);

// Answers built as JSON trees: 50 steps a number dominate.
void BM_BudgetEvaluateSurfaceAnswerTree(benchmark::State& state) {
    const int count = 100000;
    json params = json::array();
    for (int k = 0; k < count; ++k) params.push_back({(k % 1000) / 1000.0, (k / 1000) / 100.0});
    const json request = {
        {"op", "evaluate"}, {"surface", bicubic()}, {"params", params}, {"derivatives", 1}};
    run(state, request.dump(), geom::estimate_surface_evaluation(count, 3, 3, 1, false).steps);
}
BENCHMARK(BM_BudgetEvaluateSurfaceAnswerTree)->Unit(benchmark::kMillisecond);

// Streamed meshes: 5 steps a number.
void BM_BudgetTessellateStreamed(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const json request = {{"op", "tessellate"}, {"surface", bicubic()}, {"samples", {n, n}}};
    run(state, request.dump(), geom::estimate_tessellation(n, n, 3, 3).steps);
}
BENCHMARK(BM_BudgetTessellateStreamed)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);

// Expression instructions: 2.5 steps each (1,000 sine terms on a 21^3 grid).
void BM_BudgetPolygonizeLongExpression(benchmark::State& state) {
    std::string expression = "sin(x*1+y)";
    for (int k = 2; k <= 1000; ++k) expression += "+sin(x*" + std::to_string(k) + "+y)";
    const json request = {{"op", "polygonize"},
                          {"implicit", expression},
                          {"bounds", {{-1, -1, -1}, {1, 1, 1}}},
                          {"cell", 0.1}};
    // 5,999 instructions after folding (the protocol's own count, see its limit message).
    run(state, request.dump(), geom::estimate_polygonization(21.0 * 21 * 21, 5999).steps);
}
BENCHMARK(BM_BudgetPolygonizeLongExpression)->Unit(benchmark::kMillisecond);

} // namespace
