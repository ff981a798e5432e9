// Peak FMA kernels and divider kernels, one per register width, compiled for their ISA by
// target attributes and run only where the CPU has it. Accumulators are separate variables (not an
// array, which the compiler may keep in memory and so measure store forwarding instead): 12
// independent chains cover FMA latency 4-5 cycles x 2 FMA pipes on current x86 cores.
#include "tests/bench/compare/peak_fma.hpp"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace isoparm::bench {

#if defined(__x86_64__)

#define ISOPARM_PEAK_BODY(V, FMA, SET1, ADD, STORE, W)                                             \
    V a0 = SET1(1.00), a1 = SET1(1.01), a2 = SET1(1.02), a3 = SET1(1.03), a4 = SET1(1.04),         \
      a5 = SET1(1.05), a6 = SET1(1.06), a7 = SET1(1.07), a8 = SET1(1.08), a9 = SET1(1.09),         \
      a10 = SET1(1.10), a11 = SET1(1.11);                                                          \
    const V m = SET1(0.999999), c = SET1(1e-7);                                                    \
    for (std::uint64_t r = 0; r < rounds; ++r) {                                                   \
        a0 = FMA(a0, m, c);                                                                        \
        a1 = FMA(a1, m, c);                                                                        \
        a2 = FMA(a2, m, c);                                                                        \
        a3 = FMA(a3, m, c);                                                                        \
        a4 = FMA(a4, m, c);                                                                        \
        a5 = FMA(a5, m, c);                                                                        \
        a6 = FMA(a6, m, c);                                                                        \
        a7 = FMA(a7, m, c);                                                                        \
        a8 = FMA(a8, m, c);                                                                        \
        a9 = FMA(a9, m, c);                                                                        \
        a10 = FMA(a10, m, c);                                                                      \
        a11 = FMA(a11, m, c);                                                                      \
    }                                                                                              \
    V t = ADD(ADD(ADD(a0, a1), ADD(a2, a3)), ADD(ADD(a4, a5), ADD(a6, a7)));                       \
    t = ADD(t, ADD(ADD(a8, a9), ADD(a10, a11)));                                                   \
    double out[W];                                                                                 \
    STORE(out, t);                                                                                 \
    double s = 0;                                                                                  \
    for (double x : out) s += x;                                                                   \
    *sink = s;                                                                                     \
    return rounds * 12 * W;

__attribute__((target("avx2,fma"))) static std::uint64_t peak4(std::uint64_t rounds, double* sink) {
    ISOPARM_PEAK_BODY(__m256d, _mm256_fmadd_pd, _mm256_set1_pd, _mm256_add_pd, _mm256_storeu_pd, 4)
}

__attribute__((target("avx512f"))) static std::uint64_t peak8(std::uint64_t rounds, double* sink) {
    ISOPARM_PEAK_BODY(__m512d, _mm512_fmadd_pd, _mm512_set1_pd, _mm512_add_pd, _mm512_storeu_pd, 8)
}

// The divider: 8 independent chains of x = c / x (or c / sqrt(x)), enough to keep a divider
// of 4-16 cycles' throughput and 13-40 cycles' latency busy. c is slightly above 1 and the
// chains start in [1, 2): the values stay normal numbers (no slow paths).
#define ISOPARM_DIVIDE_BODY(V, DIV, SQRT, SET1, ADD, STORE, W)                                     \
    V a0 = SET1(1.10), a1 = SET1(1.21), a2 = SET1(1.32), a3 = SET1(1.43), a4 = SET1(1.54),         \
      a5 = SET1(1.65), a6 = SET1(1.76), a7 = SET1(1.87);                                           \
    const V c = SET1(1.0000001);                                                                   \
    if (with_sqrt) {                                                                               \
        for (std::uint64_t r = 0; r < rounds; ++r) {                                               \
            a0 = DIV(c, SQRT(a0));                                                                 \
            a1 = DIV(c, SQRT(a1));                                                                 \
            a2 = DIV(c, SQRT(a2));                                                                 \
            a3 = DIV(c, SQRT(a3));                                                                 \
            a4 = DIV(c, SQRT(a4));                                                                 \
            a5 = DIV(c, SQRT(a5));                                                                 \
            a6 = DIV(c, SQRT(a6));                                                                 \
            a7 = DIV(c, SQRT(a7));                                                                 \
        }                                                                                          \
    } else {                                                                                       \
        for (std::uint64_t r = 0; r < rounds; ++r) {                                               \
            a0 = DIV(c, a0);                                                                       \
            a1 = DIV(c, a1);                                                                       \
            a2 = DIV(c, a2);                                                                       \
            a3 = DIV(c, a3);                                                                       \
            a4 = DIV(c, a4);                                                                       \
            a5 = DIV(c, a5);                                                                       \
            a6 = DIV(c, a6);                                                                       \
            a7 = DIV(c, a7);                                                                       \
        }                                                                                          \
    }                                                                                              \
    V t = ADD(ADD(ADD(a0, a1), ADD(a2, a3)), ADD(ADD(a4, a5), ADD(a6, a7)));                       \
    double out[W];                                                                                 \
    STORE(out, t);                                                                                 \
    double s = 0;                                                                                  \
    for (double x : out) s += x;                                                                   \
    *sink = s;                                                                                     \
    return rounds * 8 * W;

__attribute__((target("avx2"))) static std::uint64_t divide4(std::uint64_t rounds, bool with_sqrt,
                                                             double* sink) {
    ISOPARM_DIVIDE_BODY(__m256d, _mm256_div_pd, _mm256_sqrt_pd, _mm256_set1_pd, _mm256_add_pd,
                        _mm256_storeu_pd, 4)
}

// The masked square root: GCC 12 warns about _mm512_sqrt_pd's undefined pass-through operand.
__attribute__((target("avx512f"))) static inline __m512d sqrt8(__m512d x) {
    return _mm512_mask_sqrt_pd(x, 0xFF, x);
}

__attribute__((target("avx512f"))) static std::uint64_t divide8(std::uint64_t rounds,
                                                                bool with_sqrt, double* sink){
    ISOPARM_DIVIDE_BODY(__m512d, _mm512_div_pd, sqrt8, _mm512_set1_pd, _mm512_add_pd,
                        _mm512_storeu_pd, 8)}

std::uint64_t peak_divide_kernel(int width, bool with_sqrt, std::uint64_t rounds, double* sink) {
    return width == 8 ? divide8(rounds, with_sqrt, sink) : divide4(rounds, with_sqrt, sink);
}

// Stores only (no loads: the kernel's outputs are written, never read back), four vectors a
// step so that the loop's own work stays below one store a cycle.
__attribute__((target("avx2"))) static void store4(double* to, std::uint64_t doubles, double v) {
    const __m256d x = _mm256_set1_pd(v);
    for (std::uint64_t k = 0; k < doubles; k += 16) {
        _mm256_store_pd(to + k, x);
        _mm256_store_pd(to + k + 4, x);
        _mm256_store_pd(to + k + 8, x);
        _mm256_store_pd(to + k + 12, x);
    }
}

__attribute__((target("avx512f"))) static void store8(double* to, std::uint64_t doubles, double v) {
    const __m512d x = _mm512_set1_pd(v);
    for (std::uint64_t k = 0; k < doubles; k += 16) {
        _mm512_store_pd(to + k, x);
        _mm512_store_pd(to + k + 8, x);
    }
}

std::uint64_t peak_store_kernel(int width, double* to, std::uint64_t doubles,
                                std::uint64_t rounds) {
    doubles -= doubles % 16;
    for (std::uint64_t r = 0; r < rounds; ++r) {
        if (width == 8)
            store8(to, doubles, static_cast<double>(r));
        else
            store4(to, doubles, static_cast<double>(r));
    }
    return rounds * doubles * sizeof(double);
}

bool peak_fma_supported(int width) {
    if (width == 4) return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    if (width == 8) return __builtin_cpu_supports("avx512f");
    return false;
}

std::uint64_t peak_fma_kernel(int width, std::uint64_t rounds, double* sink) {
    return width == 8 ? peak8(rounds, sink) : peak4(rounds, sink);
}

#else

bool peak_fma_supported(int) {
    return false;
}
std::uint64_t peak_fma_kernel(int, std::uint64_t, double* sink) {
    *sink = 0;
    return 0;
}
std::uint64_t peak_divide_kernel(int, bool, std::uint64_t, double* sink) {
    *sink = 0;
    return 0;
}
std::uint64_t peak_store_kernel(int, double*, std::uint64_t, std::uint64_t) {
    return 0;
}

#endif

} // namespace isoparm::bench
