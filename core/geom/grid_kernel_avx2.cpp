// The vertex kernel built for AVX2 + FMA (this file alone gets -mavx2 -mfma).
#include "core/geom/grid_kernel.hpp"

#include "core/geom/grid_kernel.inl"

namespace isoparm::geom::kernel {
void row_avx2(const RowArgs& a) {
    dispatch(a);
}
} // namespace isoparm::geom::kernel
