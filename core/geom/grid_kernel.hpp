// The vertex kernel of GridTessellator, built three times from one source (grid_kernel.inl):
// baseline x86-64 (or any other architecture), AVX2+FMA and AVX-512, chosen at run time.
//
// Scheme (the tensor product of Piegl & Tiller A3.5, contracted one direction at a time and
// vectorized ACROSS SAMPLES, lanes = consecutive sample columns):
//   1. v first, per control row a: R_a(v_j) = sum_c N_c(v_j) Pw[a][c] for the block's sample
//      columns. Lanes of one vector fall in up to `nc` consecutive control columns, so the
//      basis is stored "banded" per chunk of `lanes` samples (zeros outside each lane's span):
//      the control points are broadcast scalars and the basis a streamed vector.
//   2. then u, per sample row i: S(u_i, v_j) = sum_r N_r(u_i) R_{first_i + r}(v_j): the u basis
//      values are the same for the whole row (kept in registers), R rows are contiguous (a
//      ring of the last p + 1 contracted rows, stored twice over).
// Step 1 costs n_u / samples_u of step 2 per point. Every lane runs the same instructions in
// the same order whatever the block or thread split, so results do not depend on either, nor
// on the path but for the baseline's unfused multiply-adds (AVX2 and AVX-512: the same bits).
// The paths' speeds against the FMA peak and the divider (1 / w per point; 1 / sqrt with
// normals), measured in one run: tests/bench/compare/bench_sisl.cpp, core/geom/README.md.
#pragma once

#include <cstddef>
#include <cstdint>

namespace isoparm::geom::kernel {

enum class Path : std::uint8_t { baseline = 0, avx2 = 1, avx512 = 2 };

// One block: sample rows i0..i1 and columns j0..j1 of the grid.
struct GridArgs {
    // u direction: (p + 1) values per sample row, first control row of each sample row.
    const double* Nu;
    const double* dNu;
    const int* first_u;
    int p;
    // v direction, banded: per chunk k of `lanes` sample columns, nc columns of `lanes` values
    // (M[(k * nc + c) * lanes + lane] multiplies control column f0[k] + c).
    const double* M;
    const double* dM;
    const int* f0;
    int nc;
    // The net: control point (a, c) at points[(a * n_v + c) * 3] (x, y, z) and weights[a * n_v
    // + c]. The block forms the homogeneous (wx, wy, wz, w) of the control columns it reads
    // itself, one control row at a time: in parallel, without a pass over the whole net per
    // call, and on the core that then reads them.
    const double* points;
    const double* weights;
    int n_v;
    int i0, i1, j0, j1;
    int samples_v; // row stride of positions / normals
    // Outputs as x, y, z triples indexed i * samples_v + j (plain doubles: the ISA builds must
    // not instantiate inline library code, an ODR hazard across builds).
    double* positions;
    double* normals; // null: positions only (no derivatives are formed)
    // The block's own rows, (i - i0) * (j1 - j0 + 1) + j - j0: 0 done, 1 degenerate normal,
    // 2 missing (the block's own bytes: blocks on other threads share no cache line with it
    // but at the ends).
    std::uint8_t* status;
    double* scratch; // scratch_doubles(*this, lanes) doubles
    bool generic;    // tests: the run-time-degree code instead of the specialised one
};

enum : std::uint8_t { vertex_ok = 0, vertex_degenerate = 1, vertex_missing = 2 };

// Lanes (sample columns per vector) of a path: 2 baseline, 4 AVX2, 8 AVX-512.
int lanes(Path path);
// Whether this build has the path and this CPU runs it.
bool supported(Path path);
// The path in use: the widest supported, or ISOPARM_SIMD=baseline|avx2|avx512 where that one
// is supported (read once; an unsupported or unknown value is ignored).
Path active_path();
const char* name(Path path);
std::size_t scratch_doubles(const GridArgs& a, int lanes);

// Evaluates the block; returns how many of its vertices are not vertex_ok.
long run(Path path, const GridArgs& a);

// The builds (run picks one).
long run_baseline(const GridArgs& a);
long run_avx2(const GridArgs& a);
long run_avx512(const GridArgs& a);

} // namespace isoparm::geom::kernel
