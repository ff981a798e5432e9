// The expression language's instruction set and the arithmetic every evaluator shares
// (internal to core/geom/implicit: expression_parser.cpp folds constants with it, expression.cpp
// and expression_dual.cpp evaluate with it, so all give the same bits).
#pragma once

#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/geom/implicit/expression.hpp"

namespace isoparm::geom::implicit::detail {

enum Op : std::uint8_t {
    op_const,   // push c
    op_x,       // push x
    op_y,       // push y
    op_z,       // push z
    op_param,   // push params[n]
    op_add,     // a b -> a + b
    op_sub,     // a b -> a - b
    op_mul,     // a b -> a * b
    op_div,     // a b -> a / b
    op_pow,     // a b -> pow(a, b)
    op_add_c,   // a -> a + c
    op_sub_c,   // a -> a - c
    op_rsub_c,  // a -> c - a
    op_mul_c,   // a -> a * c
    op_div_c,   // a -> a / c
    op_rdiv_c,  // a -> c / a
    op_pow_int, // a -> a^n by repeated multiplication
    op_pow_c,   // a -> pow(a, c), c not a small integer
    op_neg,
    op_sin,
    op_cos,
    op_tan,
    op_exp,
    op_log,
    op_sqrt,
    op_abs,
    op_store, // copy the top of the stack to slot n (a register), keeping it on the stack
    op_load,  // push a copy of slot n
};

inline bool is_binary(std::uint8_t op) {
    return op >= op_add && op <= op_pow;
}

// Stack effect of one instruction.
inline int stack_delta(std::uint8_t op) {
    switch (op) {
    case op_const:
    case op_x:
    case op_y:
    case op_z:
    case op_param:
    case op_load:
        return 1;
    default:
        return is_binary(op) ? -1 : 0;
    }
}

// Nesting (parentheses, function calls, exponents) is bounded so the parser's recursion and the
// evaluator's fixed-size stack are bounded: each level holds at most three pending operands
// (a sum's left side, a product's left side, a power's base), so the stack stays below 3 * 65 + 1.
constexpr int max_nesting = 64;
constexpr int stack_capacity = 256;
constexpr int max_int_exponent = 64; // larger integer exponents go through pow
constexpr std::size_t batch_block = 256;
constexpr std::size_t batch_rows = 64; // rows in one block of values_on_rows at most

// Common-subexpression elimination on folded postfix code (expression_share.cpp): the
// first occurrence of a repeated subexpression is followed by op_store into a register slot
// (from max_stack up, at most stack_capacity), the later ones replaced by op_load. Each
// value is computed by the same instructions as before, so every evaluator gives the same
// bits. `slots` is set to max_stack + the registers used.
std::vector<Program::Instruction>
share_subexpressions(const std::vector<Program::Instruction>& code, int max_stack, int& slots);

// a^n by binary exponentiation; x^2 and x^3 cost one and two multiplications. The special
// cases give the same bits as the loop would (1 * (a * a) == a * a).
inline double powi(double a, int n) {
    if (n == 2) return a * a;
    if (n == 3) return a * (a * a);
    if (n < 0) return 1.0 / powi(a, -n);
    double result = 1.0;
    double base = a;
    while (n != 0) {
        if (n & 1) result *= base;
        n >>= 1;
        if (n != 0) base *= base;
    }
    return result;
}

inline double apply_unary(std::uint8_t op, double a) {
    switch (op) {
    case op_neg:
        return -a;
    case op_sin:
        return std::sin(a);
    case op_cos:
        return std::cos(a);
    case op_tan:
        return std::tan(a);
    case op_exp:
        return std::exp(a);
    case op_log:
        return std::log(a);
    case op_sqrt:
        return std::sqrt(a);
    case op_abs:
        return std::fabs(a);
    default:
        assert(false && "not a unary op");
        return a;
    }
}

inline double apply_binary(std::uint8_t op, double a, double b) {
    switch (op) {
    case op_add:
        return a + b;
    case op_sub:
        return a - b;
    case op_mul:
        return a * b;
    case op_div:
        return a / b;
    case op_pow:
        return std::pow(a, b);
    default:
        assert(false && "not a binary op");
        return a;
    }
}

// One unary or constant-operand instruction on a value (the same arithmetic everywhere).
inline double apply_instruction(const Program::Instruction& in, double a) {
    switch (in.op) {
    case op_add_c:
        return a + in.c;
    case op_sub_c:
        return a - in.c;
    case op_rsub_c:
        return in.c - a;
    case op_mul_c:
        return a * in.c;
    case op_div_c:
        return a / in.c;
    case op_rdiv_c:
        return in.c / a;
    case op_pow_int:
        return powi(a, in.n);
    case op_pow_c:
        return std::pow(a, in.c);
    default:
        return apply_unary(in.op, a);
    }
}

// The batch kernels: one switch, then a loop over the lanes. m is a multiple of 4 (the lanes
// are padded) and each step handles four independent lanes, which GCC's -O2 turns into SIMD
// instructions (straight-line vectorization) with no remainder loop.
template <class F> inline void for_lanes(std::size_t m, F f) {
    for (std::size_t i = 0; i < m; i += 4) {
        f(i);
        f(i + 1);
        f(i + 2);
        f(i + 3);
    }
}

// The lane loops live in expression_lanes.cpp, built for AVX2 beside the baseline and chosen
// when the program starts (the arithmetic is the same: no fused multiply-adds, so the same bits).
void binary_lanes(std::uint8_t op, double* __restrict a, const double* __restrict b, std::size_t m);
void binary_lane_value(std::uint8_t op, double* __restrict a, double b, std::size_t m);
void binary_value_lane(std::uint8_t op, double a, const double* __restrict b,
                       double* __restrict out, std::size_t m);
void unary_lane(const Program::Instruction& in, double* __restrict a, std::size_t m);
void fill_lane(double* __restrict d, double c, std::size_t m);
void copy_lane(double* __restrict d, const double* __restrict from, std::size_t m);

// The dual evaluator's slots (expression_dual.cpp): a value lane, then `tangents` tangent
// lanes (1, 3 or 4), dual_block doubles apart; m a multiple of 4. a = a (op) b for op_add,
// op_sub, op_mul and op_div; a = f(a) for the unary instructions whose derivative is plain
// arithmetic (false, nothing done, for the others: their factors go to dual_scale_slots, which
// multiplies every tangent lane by f).
constexpr std::size_t dual_block = 256;
void dual_binary_slots(std::uint8_t op, int tangents, double* __restrict a,
                       const double* __restrict b, std::size_t m);
bool dual_unary_slots(const Program::Instruction& in, int tangents, double* __restrict a,
                      std::size_t m);
void dual_scale_slots(int tangents, double* __restrict a, const double* __restrict f,
                      std::size_t m);

} // namespace isoparm::geom::implicit::detail
