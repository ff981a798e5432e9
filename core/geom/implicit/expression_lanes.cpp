// The expression evaluators' lane loops (declared in expression_ops.hpp): one switch, then a
// loop over a block of lanes. Built twice on x86-64 with GCC, for AVX2 and for the baseline,
// and chosen by the CPU when the program starts (GCC's target_clones); both do the same IEEE
// operations in the same order (AVX2 alone has no fused multiply-add), so the same bits.
#include <cmath>
#include <cstring>

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
        else if (in.n == 4) // powi's (a a)(a a): its 1 * ... changes no bit
            for_lanes(m, [=](std::size_t i) {
                const double s = a[i] * a[i];
                a[i] = s * s;
            });
        else
            for_lanes(m, [=](std::size_t i) { a[i] = powi(a[i], in.n); });
        break;
    default:
        for_lanes(m, [=](std::size_t i) { a[i] = apply_instruction(in, a[i]); });
        break;
    }
}

// ---------------------------------------------------------------------------------------------
// The dual numbers' slots (expression_dual.cpp): a slot holds a value lane and L tangent lanes
// (L = 1, 3 or 4), dual_block doubles apart. One pass over the points does the value and every
// tangent of an instruction, where a pass per lane loaded the shared operands again each time
// (the product rule reads both values for every tangent). Each point gets evaluate_dual's
// operations in its order, with GCC's vector extension (four doubles: one AVX2 register, two
// SSE2 ones in the baseline build), so the same bits.

namespace {

typedef double Lanes4 __attribute__((vector_size(32)));

[[gnu::always_inline]] inline void load(Lanes4& v, const double* p) {
    std::memcpy(&v, p, sizeof v);
}
[[gnu::always_inline]] inline void store(double* p, const Lanes4& v) {
    std::memcpy(p, &v, sizeof v);
}

// Lane i of a slot: 0 the value, 1..L the tangents.
[[gnu::always_inline]] inline std::size_t lane(int i) {
    return static_cast<std::size_t>(i) * dual_block;
}

template <int L, std::uint8_t op>
[[gnu::always_inline]] inline void dual_binary(double* __restrict a, const double* __restrict b,
                                               std::size_t m) {
    for (std::size_t k = 0; k < m; k += 4) {
        Lanes4 av, bv, ad, bd;
        load(av, a + k);
        load(bv, b + k);
        if constexpr (op == op_div) av /= bv; // the quotient rule uses the new value
        for (int i = 1; i <= L; ++i) {
            load(ad, a + lane(i) + k);
            load(bd, b + lane(i) + k);
            if constexpr (op == op_add)
                ad += bd;
            else if constexpr (op == op_sub)
                ad -= bd;
            else if constexpr (op == op_mul)
                ad = ad * bv + av * bd; // the product rule, with a's old value
            else
                ad = (ad - av * bd) / bv;
            store(a + lane(i) + k, ad);
        }
        if constexpr (op == op_add)
            av += bv;
        else if constexpr (op == op_sub)
            av -= bv;
        else if constexpr (op == op_mul)
            av *= bv;
        store(a + k, av);
    }
}

template <int L>
[[gnu::always_inline]] inline void dual_binary(std::uint8_t op, double* __restrict a,
                                               const double* __restrict b, std::size_t m) {
    switch (op) {
    case op_add:
        dual_binary<L, op_add>(a, b, m);
        break;
    case op_sub:
        dual_binary<L, op_sub>(a, b, m);
        break;
    case op_mul:
        dual_binary<L, op_mul>(a, b, m);
        break;
    default:
        dual_binary<L, op_div>(a, b, m);
        break;
    }
}

// The tangents scaled by f: d *= f (the chain rule of a unary function).
template <int L>
[[gnu::always_inline]] inline void scale_tangents(double* __restrict a, const Lanes4& f,
                                                  std::size_t k) {
    for (int i = 1; i <= L; ++i) {
        Lanes4 d;
        load(d, a + lane(i) + k);
        d *= f;
        store(a + lane(i) + k, d);
    }
}

// The unary instructions whose factor is plain arithmetic; false for the others.
template <int L>
[[gnu::always_inline]] inline bool dual_unary(const Program::Instruction& in, double* __restrict a,
                                              std::size_t m) {
    const double c = in.c;
    const Lanes4 cs = {c, c, c, c};
    switch (in.op) {
    case op_add_c:
    case op_sub_c:
        unary_lane(in, a, m);
        return true;
    case op_rsub_c:
    case op_neg:
    case op_mul_c: {
        // evaluate_dual scales by -1 (not a negation: a NaN keeps its sign) or by c.
        const double k = in.op == op_mul_c ? c : -1.0;
        const Lanes4 f = {k, k, k, k};
        unary_lane(in, a, m);
        for (std::size_t p = 0; p < m; p += 4) scale_tangents<L>(a, f, p);
        return true;
    }
    case op_div_c:
        unary_lane(in, a, m);
        for (std::size_t k = 0; k < m; k += 4)
            for (int i = 1; i <= L; ++i) {
                Lanes4 d;
                load(d, a + lane(i) + k);
                d /= cs;
                store(a + lane(i) + k, d);
            }
        return true;
    case op_rdiv_c:
        for (std::size_t k = 0; k < m; k += 4) {
            Lanes4 v;
            load(v, a + k);
            const Lanes4 r = cs / v;
            scale_tangents<L>(a, -r / v, k);
            store(a + k, r);
        }
        return true;
    case op_pow_int:
        // powi's products (expression_ops.hpp): v^2 = v v, v^3 = v (v v), v^4 = (v v)(v v);
        // the factor n v^(n-1) as n * powi(v, n - 1).
        if (in.n < 2 || in.n > 4) return false;
        for (std::size_t k = 0; k < m; k += 4) {
            Lanes4 v;
            load(v, a + k);
            const Lanes4 v2 = v * v;
            if (in.n == 2) {
                scale_tangents<L>(a, 2.0 * v, k);
                store(a + k, v2);
            } else if (in.n == 3) {
                scale_tangents<L>(a, 3.0 * v2, k);
                store(a + k, v * v2);
            } else {
                scale_tangents<L>(a, 4.0 * (v * v2), k);
                store(a + k, v2 * v2);
            }
        }
        return true;
    default:
        return false;
    }
}

} // namespace

ISOPARM_LANES void dual_binary_slots(std::uint8_t op, int tangents, double* __restrict a,
                                     const double* __restrict b, std::size_t m) {
    switch (tangents) {
    case 1:
        dual_binary<1>(op, a, b, m);
        break;
    case 3:
        dual_binary<3>(op, a, b, m);
        break;
    default:
        dual_binary<4>(op, a, b, m);
        break;
    }
}

ISOPARM_LANES bool dual_unary_slots(const Program::Instruction& in, int tangents,
                                    double* __restrict a, std::size_t m) {
    switch (tangents) {
    case 1:
        return dual_unary<1>(in, a, m);
    case 3:
        return dual_unary<3>(in, a, m);
    default:
        return dual_unary<4>(in, a, m);
    }
}

ISOPARM_LANES void dual_scale_slots(int tangents, double* __restrict a, const double* __restrict f,
                                    std::size_t m) {
    for (std::size_t k = 0; k < m; k += 4) {
        Lanes4 fk;
        load(fk, f + k);
        switch (tangents) {
        case 1:
            scale_tangents<1>(a, fk, k);
            break;
        case 3:
            scale_tangents<3>(a, fk, k);
            break;
        default:
            scale_tangents<4>(a, fk, k);
            break;
        }
    }
}

// std::fill_n and std::copy_n are not vectorized at -O2 (an unknown trip count); four lanes a
// step are.
ISOPARM_LANES void fill_lane(double* __restrict d, double c, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = c; });
}

ISOPARM_LANES void copy_lane(double* __restrict d, const double* __restrict from, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = from[k]; });
}

} // namespace isoparm::geom::implicit::detail
