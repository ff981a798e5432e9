// The expression's values: one point (value) and a row of points (values_along_x, the
// polygonizer's grid sampling), bit-identical to each other. The parser is in
// expression_parser.cpp, the derivatives in expression_dual.cpp.
#include "core/geom/implicit/expression.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "core/geom/implicit/expression_ops.hpp"

namespace isoparm::geom::implicit {

using namespace detail;

double Program::value(const glm::dvec3& p, const double* params) const {
    assert(params != nullptr || parameter_names_.empty());
    double s[stack_capacity];
    int sp = 0;
    for (const Instruction& in : run().code) {
        switch (in.op) {
        case op_store:
            s[in.n] = s[sp - 1];
            break;
        case op_load:
            s[sp++] = s[in.n];
            break;
        case op_const:
            s[sp++] = in.c;
            break;
        case op_x:
            s[sp++] = p.x;
            break;
        case op_y:
            s[sp++] = p.y;
            break;
        case op_z:
            s[sp++] = p.z;
            break;
        case op_param:
            s[sp++] = params[in.n];
            break;
        case op_add:
            --sp;
            s[sp - 1] += s[sp];
            break;
        case op_sub:
            --sp;
            s[sp - 1] -= s[sp];
            break;
        case op_mul:
            --sp;
            s[sp - 1] *= s[sp];
            break;
        case op_div:
            --sp;
            s[sp - 1] /= s[sp];
            break;
        case op_pow:
            --sp;
            s[sp - 1] = std::pow(s[sp - 1], s[sp]);
            break;
        case op_add_c:
            s[sp - 1] += in.c;
            break;
        case op_sub_c:
            s[sp - 1] -= in.c;
            break;
        case op_rsub_c:
            s[sp - 1] = in.c - s[sp - 1];
            break;
        case op_mul_c:
            s[sp - 1] *= in.c;
            break;
        case op_div_c:
            s[sp - 1] /= in.c;
            break;
        case op_rdiv_c:
            s[sp - 1] = in.c / s[sp - 1];
            break;
        case op_pow_int:
            s[sp - 1] = powi(s[sp - 1], in.n);
            break;
        case op_pow_c:
            s[sp - 1] = std::pow(s[sp - 1], in.c);
            break;
        default:
            s[sp - 1] = apply_unary(in.op, s[sp - 1]);
            break;
        }
    }
    return s[0];
}

void Program::values_along_x(const double* xs, std::size_t n, double y, double z, double* out,
                             const double* params, std::vector<double>& scratch) const {
    values_on_rows(xs, n, &y, 1, z, out, params, scratch);
}

namespace {

// What a slot of the row evaluator holds: one value for the whole block (constants, parameters,
// z and what is computed from them alone), one value per row (y-dependent, x-independent), or
// one value per point.
enum class Holds : std::uint8_t { block, row, point };

// A block of the row evaluator: `rows` rows of `m` points each (the points of row r at lanes
// r m .. r m + m - 1), the lane count padded to a multiple of 4.
struct RowBlock {
    const double* xs; // the block's m x values
    const double* ys; // its rows' y values
    std::size_t m, rows, padded;
};

// Runs the code over one block; the result (slot 0) is what it holds: `top` points at its
// values per point or per row, or top_value is its one value.
Holds run_block(const std::vector<Program::Instruction>& code, const RowBlock& b, double z,
                const double* params, double* scratch, std::size_t slot_size, const double*& top,
                double& top_value) {
    Holds holds[stack_capacity];
    double value[stack_capacity]; // the values of the slots that hold one
    const auto lanes = [&](int s) { return scratch + static_cast<std::size_t>(s) * slot_size; };
    const auto row_values = [&](int s) { return lanes(s) + batch_block; };
    // A slot of row values as one value per point, for an instruction with a slot of points.
    const auto spread = [&](int s) {
        if (holds[s] != Holds::row) return;
        for (std::size_t r = 0; r < b.rows; ++r)
            std::fill_n(lanes(s) + r * b.m, b.m, row_values(s)[r]);
        holds[s] = Holds::point;
    };
    const auto row_or_block = [&](int s, std::size_t r) {
        return holds[s] == Holds::row ? row_values(s)[r] : value[s];
    };
    const auto copy = [&](int from, int to) {
        holds[to] = holds[from];
        if (holds[from] == Holds::point)
            std::copy_n(lanes(from), b.padded, lanes(to));
        else if (holds[from] == Holds::row)
            std::copy_n(row_values(from), b.rows, row_values(to));
        else
            value[to] = value[from];
    };
    // A loaded register is copied onto the stack only when something changes it there: the
    // right operand of a binary instruction (the usual next one) is read in place.
    int loaded = -1; // the register that the top of the stack is still, or -1
    int sp = 0;
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
            value[sp] = in.c, holds[sp++] = Holds::block;
            break;
        case op_x:
            for (std::size_t r = 0; r < b.rows; ++r) std::copy_n(b.xs, b.m, lanes(sp) + r * b.m);
            holds[sp++] = Holds::point;
            break;
        case op_y:
            std::copy_n(b.ys, b.rows, row_values(sp));
            holds[sp++] = Holds::row;
            break;
        case op_z:
            value[sp] = z, holds[sp++] = Holds::block;
            break;
        case op_param:
            value[sp] = params[in.n], holds[sp++] = Holds::block;
            break;
        case op_add:
        case op_sub:
        case op_mul:
        case op_div:
        case op_pow: {
            const int a = sp - 2, c = loaded >= 0 ? loaded : sp - 1;
            --sp;
            loaded = -1;
            if (holds[a] == Holds::block && holds[c] == Holds::block) {
                value[a] = apply_binary(in.op, value[a], value[c]);
            } else if (holds[a] != Holds::point && holds[c] != Holds::point) {
                for (std::size_t r = 0; r < b.rows; ++r)
                    row_values(a)[r] = apply_binary(in.op, row_or_block(a, r), row_or_block(c, r));
                holds[a] = Holds::row;
            } else {
                spread(a);
                spread(c);
                if (holds[a] == Holds::point && holds[c] == Holds::point)
                    binary_lanes(in.op, lanes(a), lanes(c), b.padded);
                else if (holds[a] == Holds::point)
                    binary_lane_value(in.op, lanes(a), value[c], b.padded);
                else
                    binary_value_lane(in.op, value[a], lanes(c), lanes(a), b.padded);
                holds[a] = Holds::point;
            }
            break;
        }
        default: {
            const int a = sp - 1;
            if (holds[a] == Holds::point)
                unary_lane(in, lanes(a), b.padded);
            else if (holds[a] == Holds::row)
                for (std::size_t r = 0; r < b.rows; ++r)
                    row_values(a)[r] = apply_instruction(in, row_values(a)[r]);
            else
                value[a] = apply_instruction(in, value[a]);
            break;
        }
        }
    }
    if (loaded >= 0) copy(loaded, 0);
    top = holds[0] == Holds::point ? lanes(0) : row_values(0);
    top_value = value[0];
    return holds[0];
}

} // namespace

void Program::values_on_rows(const double* xs, std::size_t n, const double* ys, std::size_t rows,
                             double z, double* out, const double* params,
                             std::vector<double>& scratch) const {
    assert(params != nullptr || parameter_names_.empty());
    if (n == 0 || rows == 0) return;
    const Code& program = run();
    // Per slot: batch_block lanes of points, then batch_rows values of rows.
    const std::size_t slot_size = batch_block + batch_rows;
    const std::size_t need = static_cast<std::size_t>(program.slots) * slot_size;
    if (scratch.size() < need) scratch.resize(need);
    // Rows shorter than a block are taken several at a time: an instruction's dispatch is paid
    // once per block (the gallery's rows are 51 to 113 points: one to five rows a block).
    const std::size_t m = std::min(n, batch_block);
    const std::size_t per_block = std::min(batch_rows, batch_block / m);
    for (std::size_t r0 = 0; r0 < rows; r0 += per_block)
        for (std::size_t first = 0; first < n; first += m) {
            const std::size_t width = std::min(m, n - first);
            const std::size_t count = std::min(per_block, rows - r0);
            const std::size_t lanes = width * count;
            const RowBlock block{xs + first, ys + r0, width, count, (lanes + 3) & ~std::size_t{3}};
            const double* top = nullptr;
            double top_value = 0.0;
            const Holds holds = run_block(program.code, block, z, params, scratch.data(), slot_size,
                                          top, top_value);
            for (std::size_t r = 0; r < count; ++r) {
                double* o = out + (r0 + r) * n + first;
                if (holds == Holds::point)
                    std::copy_n(top + r * width, width, o);
                else
                    std::fill_n(o, width, holds == Holds::row ? top[r] : top_value);
            }
        }
}

} // namespace isoparm::geom::implicit
