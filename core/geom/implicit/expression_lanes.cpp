// The expression evaluators' lane loops (declared in expression_ops.hpp): one switch, then a
// loop over a block of lanes. Built twice on x86-64 with GCC, for AVX2 and for the baseline,
// and chosen by the CPU when the program starts (GCC's target_clones); both do the same IEEE
// operations in the same order (AVX2 alone has no fused multiply-add), so the same bits.
#include <cmath>

#include "core/geom/implicit/expression_ops.hpp"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__EMSCRIPTEN__)
#define ISOPARM_LANES [[gnu::target_clones("avx2", "default")]]
#else
#define ISOPARM_LANES
#endif

namespace isoparm::geom::implicit::detail {

ISOPARM_LANES void binary_lanes(std::uint8_t op, double* __restrict a, const double* __restrict b,
                                std::size_t m) {
    switch (op) {
    case op_add:
        for_lanes(m, [=](std::size_t i) { a[i] += b[i]; });
        break;
    case op_sub:
        for_lanes(m, [=](std::size_t i) { a[i] -= b[i]; });
        break;
    case op_mul:
        for_lanes(m, [=](std::size_t i) { a[i] *= b[i]; });
        break;
    case op_div:
        for_lanes(m, [=](std::size_t i) { a[i] /= b[i]; });
        break;
    default:
        for_lanes(m, [=](std::size_t i) { a[i] = std::pow(a[i], b[i]); });
        break;
    }
}

ISOPARM_LANES void binary_lane_value(std::uint8_t op, double* __restrict a, double b,
                                     std::size_t m) {
    switch (op) {
    case op_add:
        for_lanes(m, [=](std::size_t i) { a[i] += b; });
        break;
    case op_sub:
        for_lanes(m, [=](std::size_t i) { a[i] -= b; });
        break;
    case op_mul:
        for_lanes(m, [=](std::size_t i) { a[i] *= b; });
        break;
    case op_div:
        for_lanes(m, [=](std::size_t i) { a[i] /= b; });
        break;
    default:
        for_lanes(m, [=](std::size_t i) { a[i] = std::pow(a[i], b); });
        break;
    }
}

ISOPARM_LANES void binary_value_lane(std::uint8_t op, double a, const double* __restrict b,
                                     double* __restrict out, std::size_t m) {
    switch (op) {
    case op_add:
        for_lanes(m, [=](std::size_t i) { out[i] = a + b[i]; });
        break;
    case op_sub:
        for_lanes(m, [=](std::size_t i) { out[i] = a - b[i]; });
        break;
    case op_mul:
        for_lanes(m, [=](std::size_t i) { out[i] = a * b[i]; });
        break;
    case op_div:
        for_lanes(m, [=](std::size_t i) { out[i] = a / b[i]; });
        break;
    default:
        for_lanes(m, [=](std::size_t i) { out[i] = std::pow(a, b[i]); });
        break;
    }
}

ISOPARM_LANES void unary_lane(const Program::Instruction& in, double* __restrict a, std::size_t m) {
    const double c = in.c;
    switch (in.op) {
    case op_add_c:
        for_lanes(m, [=](std::size_t i) { a[i] += c; });
        break;
    case op_sub_c:
        for_lanes(m, [=](std::size_t i) { a[i] -= c; });
        break;
    case op_rsub_c:
        for_lanes(m, [=](std::size_t i) { a[i] = c - a[i]; });
        break;
    case op_mul_c:
        for_lanes(m, [=](std::size_t i) { a[i] *= c; });
        break;
    case op_div_c:
        for_lanes(m, [=](std::size_t i) { a[i] /= c; });
        break;
    case op_rdiv_c:
        for_lanes(m, [=](std::size_t i) { a[i] = c / a[i]; });
        break;
    case op_neg:
        for_lanes(m, [=](std::size_t i) { a[i] = -a[i]; });
        break;
    case op_pow_int:
        if (in.n == 2)
            for_lanes(m, [=](std::size_t i) { a[i] = a[i] * a[i]; });
        else if (in.n == 3)
            for_lanes(m, [=](std::size_t i) { a[i] = a[i] * (a[i] * a[i]); });
        else
            for_lanes(m, [=](std::size_t i) { a[i] = powi(a[i], in.n); });
        break;
    default:
        for_lanes(m, [=](std::size_t i) { a[i] = apply_instruction(in, a[i]); });
        break;
    }
}

// d = d * bv + av * bd (the product rule, with a's old value).
ISOPARM_LANES void product_tangent(double* __restrict d, const double* __restrict bv,
                                   const double* __restrict av, const double* __restrict bd,
                                   std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = d[k] * bv[k] + av[k] * bd[k]; });
}

// d = (d - q * bd) / bv (the quotient rule, q the new value).
ISOPARM_LANES void quotient_tangent(double* __restrict d, const double* __restrict q,
                                    const double* __restrict bd, const double* __restrict bv,
                                    std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = (d[k] - q[k] * bd[k]) / bv[k]; });
}

// std::fill_n and std::copy_n are not vectorized at -O2 (an unknown trip count); four lanes a
// step are.
ISOPARM_LANES void fill_lane(double* __restrict d, double c, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = c; });
}

ISOPARM_LANES void copy_lane(double* __restrict d, const double* __restrict from, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = from[k]; });
}

ISOPARM_LANES void scale_lane(double* __restrict d, const double* __restrict f, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] *= f[k]; });
}

ISOPARM_LANES void scale_lane_by(double* __restrict d, double f, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] *= f; });
}

ISOPARM_LANES void divide_lane_by(double* __restrict d, double f, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] /= f; });
}

} // namespace isoparm::geom::implicit::detail
