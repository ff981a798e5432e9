// The machine's ceiling: the peak double-precision multiply-add rate of one core.
#pragma once

#include <cstdint>

namespace isoparm::bench {

// Runs `rounds` rounds of independent fused multiply-adds and returns how many were done
// (the kernel keeps enough independent accumulators to fill every FMA pipe).
std::uint64_t peak_fma_kernel(std::uint64_t rounds, double* sink);

} // namespace isoparm::bench
