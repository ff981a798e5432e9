// Values with derivatives: forward-mode dual numbers through the program, one point at a time
// and in blocks of points (the polygonizer's edge refinement).
#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/expression_ops.hpp"

namespace isoparm::geom::implicit {
namespace {

using namespace detail;

// Forward-mode automatic differentiation: a value and N tangent components carried through
// every operation by the chain rule (N = 3: the gradient; N = 1: a directional derivative).
// The value part uses exactly the arithmetic of value(), so both give the same bits.
// Three tangents are stored as four (the last is always 0) so that every operation handles the
// tangents as whole SIMD pairs; mixing pair and single accesses to the same memory makes the
// CPU stall on store forwarding, which at -O3 cost more than the arithmetic.
template <int N> constexpr int lanes_for = N == 3 ? 4 : N;

template <int N> struct Dual {
    double d[lanes_for<N>];
    double v;
};

// The tangent parts scaled by k (the chain rule of a unary function: d f(a) = f'(a) da).
template <int N> [[gnu::always_inline]] inline void scale(Dual<N>& a, double k) {
    for (int i = 0; i < lanes_for<N>; ++i) a.d[i] *= k;
}

// a = a (op) b for the five binary instructions, value and tangents.
template <int N>
[[gnu::always_inline]] inline void dual_binary(std::uint8_t op, Dual<N>& a, const Dual<N>& r) {
    constexpr int L = lanes_for<N>;
    switch (op) {
    case op_add:
        for (int i = 0; i < L; ++i) a.d[i] += r.d[i];
        a.v += r.v;
        break;
    case op_sub:
        for (int i = 0; i < L; ++i) a.d[i] -= r.d[i];
        a.v -= r.v;
        break;
    case op_mul:
        for (int i = 0; i < L; ++i) a.d[i] = a.d[i] * r.v + a.v * r.d[i];
        a.v *= r.v;
        break;
    case op_div: {
        const double v = a.v / r.v;
        for (int i = 0; i < L; ++i) a.d[i] = (a.d[i] - v * r.d[i]) / r.v;
        a.v = v;
        break;
    }
    default: {
        // op_pow: d(a^b) = b a^(b-1) da + a^b log(a) db; the log term only where b varies, so
        // a constant exponent does not turn the derivative into NaN for a <= 0.
        const double v = std::pow(a.v, r.v);
        const double da = r.v * std::pow(a.v, r.v - 1.0);
        bool varies = false;
        for (int i = 0; i < L; ++i) varies = varies || r.d[i] != 0.0;
        const double db = varies ? v * std::log(a.v) : 0.0;
        for (int i = 0; i < L; ++i) a.d[i] = a.d[i] * da + (varies ? r.d[i] * db : 0.0);
        a.v = v;
        break;
    }
    }
}

// a = f(a) for the unary and constant-operand instructions, value and tangents.
template <int N>
[[gnu::always_inline]] inline void dual_unary(const Program::Instruction& in, Dual<N>& a) {
    switch (in.op) {
    case op_add_c:
        a.v += in.c;
        break;
    case op_sub_c:
        a.v -= in.c;
        break;
    case op_rsub_c:
        a.v = in.c - a.v;
        scale(a, -1.0);
        break;
    case op_mul_c:
        a.v *= in.c;
        scale(a, in.c);
        break;
    case op_div_c:
        a.v /= in.c;
        for (int i = 0; i < lanes_for<N>; ++i) a.d[i] /= in.c;
        break;
    case op_rdiv_c: {
        const double v = in.c / a.v;
        scale(a, -v / a.v);
        a.v = v;
        break;
    }
    case op_pow_int:
        if (in.n == 2) {
            scale(a, 2.0 * a.v);
            a.v = a.v * a.v;
        } else {
            scale(a, in.n == 0 ? 0.0 : in.n * powi(a.v, in.n - 1));
            a.v = powi(a.v, in.n);
        }
        break;
    case op_pow_c:
        scale(a, in.c * std::pow(a.v, in.c - 1.0));
        a.v = std::pow(a.v, in.c);
        break;
    case op_neg:
        a.v = -a.v;
        scale(a, -1.0);
        break;
    case op_sin:
        scale(a, std::cos(a.v));
        a.v = std::sin(a.v);
        break;
    case op_cos:
        scale(a, -std::sin(a.v));
        a.v = std::cos(a.v);
        break;
    case op_tan: {
        const double t = std::tan(a.v);
        scale(a, 1.0 + t * t);
        a.v = t;
        break;
    }
    case op_exp: {
        const double e = std::exp(a.v);
        scale(a, e);
        a.v = e;
        break;
    }
    case op_log:
        scale(a, 1.0 / a.v);
        a.v = std::log(a.v);
        break;
    case op_sqrt: {
        const double r = std::sqrt(a.v);
        scale(a, 0.5 / r);
        a.v = r;
        break;
    }
    case op_abs:
        // The derivative of |a| is sign(a), and 0 at a = 0 (a subgradient).
        scale(a, a.v > 0 ? 1.0 : (a.v < 0 ? -1.0 : 0.0));
        a.v = std::fabs(a.v);
        break;
    default:
        assert(false && "unknown opcode");
    }
}

template <int N>
double evaluate_dual(const std::vector<Program::Instruction>& code, const glm::dvec3& p,
                     const double (&seed)[3][N], const double* params, double (&tangent)[N]) {
    constexpr int L = lanes_for<N>;
    Dual<N> stack[stack_capacity];
    Dual<N>* end = stack; // one past the top of the stack
    auto push_constant = [&](double v) {
        end->v = v;
        for (int i = 0; i < L; ++i) end->d[i] = 0.0;
        ++end;
    };
    auto push_variable = [&](double v, const double(&d)[N]) {
        end->v = v;
        for (int i = 0; i < L; ++i) end->d[i] = i < N ? d[i] : 0.0;
        ++end;
    };
    for (const Program::Instruction& in : code) {
        switch (in.op) {
        case op_store:
            stack[in.n] = end[-1];
            break;
        case op_load:
            *end++ = stack[in.n];
            break;
        case op_const:
            push_constant(in.c);
            break;
        case op_x:
            push_variable(p.x, seed[0]);
            break;
        case op_y:
            push_variable(p.y, seed[1]);
            break;
        case op_z:
            push_variable(p.z, seed[2]);
            break;
        case op_param:
            push_constant(params[in.n]);
            break;
        case op_add:
        case op_sub:
        case op_mul:
        case op_div:
        case op_pow: {
            const Dual<N>& r = *--end;
            dual_binary(in.op, end[-1], r);
            break;
        }
        default:
            dual_unary(in, end[-1]);
        }
    }
    assert(end == stack + 1);
    for (int i = 0; i < N; ++i) tangent[i] = stack[0].d[i];
    return stack[0].v;
}

// The batch form of evaluate_dual: each stack slot holds a value lane and L tangent lanes of up
// to dual_block points, so an instruction is dispatched once per block instead of once per
// point. Every lane does exactly evaluate_dual's arithmetic in the same order (the padding
// tangent of N = 3 included where the program has op_pow: a NaN there makes op_pow take its log
// term, and the batch must do the same; nothing else reads it, so without op_pow L = 3), so each
// point gets the same bits as a call of its own. The arithmetic instructions run as one pass
// over the slot's lanes (dual_binary_slots, dual_unary_slots in expression_lanes.cpp, built
// for AVX2 too); op_pow and the functions compute their factors here one point at a time.
template <int L> struct DualLanes {
    double* v;
    double* d[L];
};

template <int N> std::size_t dual_scratch_size(int slots) {
    // The slots, then one lane of per-point factors.
    return (static_cast<std::size_t>(slots) * (1 + lanes_for<N>)+1) * dual_block;
}

// a = a (op) b over the lanes for the five binary instructions (evaluate_dual's dual_binary).
template <int L>
[[gnu::always_inline]] inline void binary_dual_lanes(std::uint8_t op, const DualLanes<L>& a,
                                                     const DualLanes<L>& b, std::size_t padded) {
    if (op != op_pow) {
        dual_binary_slots(op, L, a.v, b.v, padded);
        return;
    }
    for (std::size_t k = 0; k < padded; ++k) {
        const double v = std::pow(a.v[k], b.v[k]);
        const double da = b.v[k] * std::pow(a.v[k], b.v[k] - 1.0);
        bool varies = false;
        for (int i = 0; i < L; ++i) varies = varies || b.d[i][k] != 0.0;
        const double db = varies ? v * std::log(a.v[k]) : 0.0;
        for (int i = 0; i < L; ++i) a.d[i][k] = a.d[i][k] * da + (varies ? b.d[i][k] * db : 0.0);
        a.v[k] = v;
    }
}

// a = f(a) over the lanes for the unary and constant-operand instructions (evaluate_dual's
// dual_unary); f: one lane of scratch for the per-point factors of the functions.
template <int L>
[[gnu::always_inline]] inline void unary_dual_lanes(const Program::Instruction& in,
                                                    const DualLanes<L>& a, double* f,
                                                    std::size_t padded) {
    if (dual_unary_slots(in, L, a.v, padded)) return;
    double* const v = a.v;
    const double c = in.c;
    switch (in.op) {
    case op_pow_int: {
        const int n = in.n;
        for (std::size_t k = 0; k < padded; ++k) {
            f[k] = n == 0 ? 0.0 : n * powi(v[k], n - 1);
            v[k] = powi(v[k], n);
        }
        break;
    }
    case op_pow_c:
        for (std::size_t k = 0; k < padded; ++k) {
            f[k] = c * std::pow(v[k], c - 1.0);
            v[k] = std::pow(v[k], c);
        }
        break;
    case op_sin:
        for (std::size_t k = 0; k < padded; ++k) {
            f[k] = std::cos(v[k]);
            v[k] = std::sin(v[k]);
        }
        break;
    case op_cos:
        for (std::size_t k = 0; k < padded; ++k) {
            f[k] = -std::sin(v[k]);
            v[k] = std::cos(v[k]);
        }
        break;
    case op_tan:
        for (std::size_t k = 0; k < padded; ++k) {
            const double t = std::tan(v[k]);
            f[k] = 1.0 + t * t;
            v[k] = t;
        }
        break;
    case op_exp:
        for (std::size_t k = 0; k < padded; ++k) f[k] = v[k] = std::exp(v[k]);
        break;
    case op_log:
        for (std::size_t k = 0; k < padded; ++k) {
            f[k] = 1.0 / v[k];
            v[k] = std::log(v[k]);
        }
        break;
    case op_sqrt:
        for (std::size_t k = 0; k < padded; ++k) {
            const double r = std::sqrt(v[k]);
            f[k] = 0.5 / r;
            v[k] = r;
        }
        break;
    case op_abs:
        for (std::size_t k = 0; k < padded; ++k) {
            f[k] = v[k] > 0 ? 1.0 : (v[k] < 0 ? -1.0 : 0.0);
            v[k] = std::fabs(v[k]);
        }
        break;
    default:
        assert(false && "unknown opcode");
        return;
    }
    dual_scale_slots(L, a.v, f, padded);
}

// directions: the tangent seeds of x, y, z per point (N = 1); nullptr: unit seeds (N = 3).
template <int N, int L>
void evaluate_dual_lanes(const std::vector<Program::Instruction>& code, int slots,
                         const glm::dvec3* points, const glm::dvec3* directions, std::size_t m,
                         const double* params, double* scratch, double* values, double* tangents) {

    const std::size_t padded = (m + 3) & ~std::size_t{3}; // dual_block is a multiple of 4
    auto slot = [&](int s) {
        DualLanes<L> lanes;
        double* base = scratch + static_cast<std::size_t>(s) * (1 + L) * dual_block;
        lanes.v = base;
        for (int i = 0; i < L; ++i) lanes.d[i] = base + (1 + i) * dual_block;
        return lanes;
    };
    int sp = 0;
    double* const f = scratch + static_cast<std::size_t>(slots) * (1 + L) * dual_block;
    const auto copy = [&](int from_slot, int to_slot) {
        const DualLanes<L> from = slot(from_slot), to = slot(to_slot);
        copy_lane(to.v, from.v, padded);
        for (int i = 0; i < L; ++i) copy_lane(to.d[i], from.d[i], padded);
    };
    // A loaded register is copied onto the stack only when something changes it there: the
    // right operand of a binary instruction (the usual next one) is read in place.
    int loaded = -1; // the register that the top of the stack is still, or -1
    for (const Program::Instruction& in : code) {
        if (loaded >= 0 && !is_binary(in.op)) {
            copy(loaded, sp - 1);
            loaded = -1;
        }
        switch (in.op) {
        case op_store:
            copy(sp - 1, in.n);
            break;
        case op_load:
            loaded = in.n;
            ++sp;
            break;
        case op_const:
        case op_param: {
            const DualLanes<L> a = slot(sp++);
            fill_lane(a.v, in.op == op_const ? in.c : params[in.n], padded);
            for (int i = 0; i < L; ++i) fill_lane(a.d[i], 0.0, padded);
            break;
        }
        case op_x:
        case op_y:
        case op_z: {
            const DualLanes<L> a = slot(sp++);
            const int var = in.op - op_x;
            // Padding lanes repeat the last point: they compute something harmless, never read.
            for (std::size_t k = 0; k < m; ++k) a.v[k] = points[k][var];
            std::fill(a.v + m, a.v + padded, a.v[m - 1]);
            if constexpr (N == 1) {
                for (std::size_t k = 0; k < m; ++k) a.d[0][k] = directions[k][var];
                std::fill(a.d[0] + m, a.d[0] + padded, a.d[0][m - 1]);
            } else {
                for (int i = 0; i < L; ++i) fill_lane(a.d[i], i == var ? 1.0 : 0.0, padded);
            }
            break;
        }
        case op_add:
        case op_sub:
        case op_mul:
        case op_div:
        case op_pow:
            --sp;
            binary_dual_lanes<L>(in.op, slot(sp - 1), slot(loaded >= 0 ? loaded : sp), padded);
            loaded = -1;
            break;
        default:
            unary_dual_lanes<L>(in, slot(sp - 1), f, padded);
            break;
        }
    }
    assert(sp == 1);
    if (loaded >= 0) copy(loaded, 0);
    const DualLanes<L> top = slot(0);
    for (std::size_t k = 0; k < m; ++k) {
        values[k] = top.v[k];
        for (int i = 0; i < N; ++i) tangents[k * N + i] = top.d[i][k];
    }
}

} // namespace

double Program::value_and_gradient(const glm::dvec3& p, glm::dvec3& gradient,
                                   const double* params) const {
    assert(params != nullptr || parameter_names_.empty());
    static constexpr double seeds[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double tangent[3];
    const double v = evaluate_dual<3>(run().code, p, seeds, params, tangent);
    gradient = glm::dvec3(tangent[0], tangent[1], tangent[2]);
    return v;
}

double Program::value_and_derivative(const glm::dvec3& p, const glm::dvec3& direction,
                                     double& derivative, const double* params) const {
    assert(params != nullptr || parameter_names_.empty());
    const double seeds[3][1] = {{direction.x}, {direction.y}, {direction.z}};
    double tangent[1];
    const double v = evaluate_dual<1>(run().code, p, seeds, params, tangent);
    derivative = tangent[0];
    return v;
}

void Program::values_and_derivatives(const glm::dvec3* points, const glm::dvec3* directions,
                                     std::size_t n, double* values, double* derivatives,
                                     const double* params, std::vector<double>& scratch) const {
    assert(params != nullptr || parameter_names_.empty());
    const Code& program = run();
    const std::size_t need = dual_scratch_size<1>(program.slots);
    if (scratch.size() < need) scratch.resize(need);
    for (std::size_t first = 0; first < n; first += dual_block) {
        const std::size_t m = std::min(dual_block, n - first);
        const glm::dvec3* dirs = directions + first;
        evaluate_dual_lanes<1, 1>(program.code, program.slots, points + first, dirs, m, params,
                                  scratch.data(), values + first, derivatives + first);
    }
}

void Program::values_and_gradients(const glm::dvec3* points, std::size_t n, double* values,
                                   glm::dvec3* gradients, const double* params,
                                   std::vector<double>& scratch) const {
    assert(params != nullptr || parameter_names_.empty());
    const Code& program = run();
    const std::size_t need = dual_scratch_size<3>(program.slots);
    if (scratch.size() < need) scratch.resize(need);
    double tangents[dual_block * 3];
    for (std::size_t first = 0; first < n; first += dual_block) {
        const std::size_t m = std::min(dual_block, n - first);
        // Without op_pow nothing reads the padding tangent (see evaluate_dual_lanes): skipped.
        if (program.has_pow)
            evaluate_dual_lanes<3, 4>(program.code, program.slots, points + first, nullptr, m,
                                      params, scratch.data(), values + first, tangents);
        else
            evaluate_dual_lanes<3, 3>(program.code, program.slots, points + first, nullptr, m,
                                      params, scratch.data(), values + first, tangents);
        for (std::size_t k = 0; k < m; ++k)
            gradients[first + k] =
                glm::dvec3(tangents[k * 3], tangents[k * 3 + 1], tangents[k * 3 + 2]);
    }
}

} // namespace isoparm::geom::implicit
