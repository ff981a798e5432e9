// The vertex kernel built for AVX2 + FMA (this file alone gets -mavx2 -mfma): 4 sample
// columns per ymm register.
#include "core/geom/grid_kernel.hpp"

#define ISOPARM_KERNEL_LANES 4
#include "core/geom/grid_kernel.inl"

namespace isoparm::geom::kernel {
long run_avx2(const GridArgs& a) {
    return dispatch(a);
}
} // namespace isoparm::geom::kernel
