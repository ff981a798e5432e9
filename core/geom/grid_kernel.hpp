// The vertex loop of GridTessellator, built twice (AVX2+FMA and baseline x86-64) and chosen
// at run time; both builds compile the same source (grid_kernel.inl).
#pragma once

#include <cstdint>

namespace isoparm::geom::kernel {

// One sample row: vertices j0..j1. Q and dQ hold the row's control net contracted in u (and
// its u-derivative), 4 doubles (wx, wy, wz, w) per control column.
struct RowArgs {
    const double* N;  // (q + 1) basis values per sample column
    const double* dN; // (q + 1) first derivatives per sample column
    const int* first; // first control column per sample column
    const double* Q;
    const double* dQ;
    int q;
    int j0, j1;
    // The row's vertices as x, y, z triples, indexed by sample column. Plain doubles: the
    // AVX2 build must not instantiate inline library code (an ODR hazard across builds).
    double* positions;
    double* normals;      // null: positions only (no derivatives are formed)
    std::uint8_t* status; // out: 0 done, 1 degenerate normal, 2 point does not exist
};

enum : std::uint8_t { vertex_ok = 0, vertex_degenerate = 1, vertex_missing = 2 };

void row(const RowArgs& a);

// The two builds (kernel::row picks one).
void row_avx2(const RowArgs& a);
void row_baseline(const RowArgs& a);

} // namespace isoparm::geom::kernel
