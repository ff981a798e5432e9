// Peak FMA kernel, built with -mavx2 -mfma (this file only): 12 independent 4-wide
// accumulators cover the latency (4 cycles) times the throughput (2 per cycle) of modern cores.
#include "tests/bench/compare/peak_fma.hpp"

namespace isoparm::bench {

typedef double v4d __attribute__((vector_size(32)));

std::uint64_t peak_fma_kernel(std::uint64_t rounds, double* sink) {
    constexpr int lanes = 12;
    v4d acc[lanes];
    for (int k = 0; k < lanes; ++k) acc[k] = v4d{1.0 + k, 2.0 + k, 3.0 + k, 4.0 + k} * 1e-3;
    const v4d m = {0.999999, 0.999998, 0.999997, 0.999996};
    const v4d a = {1e-7, 2e-7, 3e-7, 4e-7};
    for (std::uint64_t r = 0; r < rounds; ++r) {
        for (int k = 0; k < lanes; ++k) acc[k] = acc[k] * m + a;
        __asm__ volatile("" : "+x"(acc[0]), "+x"(acc[6])); // keep the loop honest
    }
    v4d total = {0, 0, 0, 0};
    for (int k = 0; k < lanes; ++k) total += acc[k];
    *sink = total[0] + total[1] + total[2] + total[3];
    return rounds * lanes * 4;
}

} // namespace isoparm::bench
