// The vertex kernel for any x86-64 (or other) CPU, and the run-time choice between builds.
#include "core/geom/grid_kernel.hpp"

#include "core/geom/grid_kernel.inl"

namespace isoparm::geom::kernel {

void row_baseline(const RowArgs& a) {
    dispatch(a);
}

void row(const RowArgs& a) {
#if defined(__x86_64__) && defined(ISOPARM_HAVE_AVX2_KERNEL)
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (avx2) return row_avx2(a);
#endif
    row_baseline(a);
}

} // namespace isoparm::geom::kernel
