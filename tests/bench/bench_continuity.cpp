// Dragging the shared corner of four subpatches (a 32x32 bicubic NURBS split at u = 0.5 and
// v = 0.5) with continuity kept: the command alone, which adds the neighbours' C0 / C1
// adjustments (core/doc/patches.cpp) to a plain move. Each step merges into the drag's undo step,
// as in the window. Target: well under a millisecond, so the drag itself stays tessellation-bound.
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/doc/command.hpp"
#include "core/doc/commands.hpp"
#include "core/doc/document.hpp"

using namespace isoparm;

namespace {

struct FourPatches {
    doc::Document doc;
    doc::History history;
    std::uint64_t lower_left = 0;
    int corner_i = 0, corner_j = 0;
};

std::pair<std::uint64_t, std::uint64_t> split(FourPatches& f, std::uint64_t id, geom::Dir dir) {
    auto cmd = doc::split_object(id, dir, 0.5);
    const doc::Command* raw = cmd.get();
    f.history.execute(f.doc, std::move(cmd));
    return doc::split_piece_ids(*raw);
}

FourPatches four_patches(doc::Continuity mode) {
    FourPatches f;
    doc::Object o;
    o.name = "big";
    geom::Surface s = doc::make_planar_grid(32, 32, 3, 3, geom::SplineType::nurbs);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) s.point(i, j).z = std::sin(0.4 * i) * std::cos(0.3 * j);
    o.shape = doc::SurfaceObject{s};
    f.history.execute(f.doc, doc::add_object(o));
    f.doc.continuity = mode;
    const auto [left, right] = split(f, f.doc.objects.front().id, geom::Dir::u);
    const auto [low, high] = split(f, left, geom::Dir::v);
    split(f, right, geom::Dir::v);
    f.lower_left = low;
    const geom::Surface& ll = std::get<doc::SurfaceObject>(f.doc.find(low)->shape).surface;
    f.corner_i = ll.n_u - 1;
    f.corner_j = ll.n_v - 1;
    f.history.seal();
    (void)high;
    return f;
}

void drag_corner(benchmark::State& state, doc::Continuity mode) {
    FourPatches f = four_patches(mode);
    double t = 0;
    for (auto _ : state) {
        t += 0.01;
        f.history.execute(f.doc, doc::move_control_point(f.lower_left, f.corner_i, f.corner_j,
                                                         {0.0, 0.0, std::sin(t)}));
    }
}

void BM_CornerDragOff(benchmark::State& state) {
    drag_corner(state, doc::Continuity::off);
}
void BM_CornerDragC0(benchmark::State& state) {
    drag_corner(state, doc::Continuity::c0);
}
void BM_CornerDragC1(benchmark::State& state) {
    drag_corner(state, doc::Continuity::c1);
}
BENCHMARK(BM_CornerDragOff)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CornerDragC0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CornerDragC1)->Unit(benchmark::kMicrosecond);

} // namespace
