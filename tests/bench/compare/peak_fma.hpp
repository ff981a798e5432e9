// The machine's ceiling: the peak double-precision multiply-add rate of one core, measured
// the way the roofline model defines it (a kernel of independent FMAs in the widest vector
// registers the CPU has, enough of them in flight to cover latency x throughput), and the
// divider's: correctly rounded divisions (and square roots), which no FMA can stand in for; and
// the store bandwidth of one core into a buffer the size of a grid's output (the memory side of
// the roofline: the kernel writes 24 bytes of position a point, and as much again with normals).
#pragma once

#include <cstdint>

namespace isoparm::bench {

// Vector width of a peak kernel, in doubles: 4 (AVX2+FMA) or 8 (AVX-512F).
bool peak_fma_supported(int width);

// Runs `rounds` rounds of independent fused multiply-adds in `width`-double registers and
// returns how many scalar multiply-adds were done (2 flops each).
std::uint64_t peak_fma_kernel(int width, std::uint64_t rounds, double* sink);

// Runs `rounds` rounds of independent divisions c / x (with_sqrt: c / sqrt(x)) in
// `width`-double registers (supported as peak_fma_supported) and returns how many scalar
// divisions were done.
std::uint64_t peak_divide_kernel(int width, bool with_sqrt, std::uint64_t rounds, double* sink);

// Writes the first `doubles` doubles of `to` (64-byte aligned), rounded down to a multiple of 16,
// with aligned `width`-double stores, `rounds` times over; returns the bytes written.
std::uint64_t peak_store_kernel(int width, double* to, std::uint64_t doubles, std::uint64_t rounds);

} // namespace isoparm::bench
