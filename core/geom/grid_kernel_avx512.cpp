// The vertex kernel built for AVX-512F + FMA (this file alone gets -mavx512f -mfma): 8 sample
// columns per zmm register. Only called where the CPU reports AVX-512F (grid_kernel_baseline).
#include "core/geom/grid_kernel.hpp"

#define ISOPARM_KERNEL_LANES 8
#include "core/geom/grid_kernel.inl"

namespace isoparm::geom::kernel {
long run_avx512(const GridArgs& a) {
    return dispatch(a);
}
} // namespace isoparm::geom::kernel
