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
    assert(params != nullptr || parameter_names_.empty());
    const Code& program = run();
    const std::size_t need = static_cast<std::size_t>(program.slots) * batch_block;
    if (scratch.size() < need) scratch.resize(need);
    // The stack holds, per slot, either one value shared by every point (anything that does
    // not depend on x: y, z, parameters, constants and what is computed from them) or a lane
    // of batch_block values. Each instruction runs once per block, so dispatch is paid once per
    // block, and x-independent work once per block instead of once per point.
    double uniform[stack_capacity];
    bool varying[stack_capacity];
    for (std::size_t first = 0; first < n; first += batch_block) {
        const std::size_t m = std::min(batch_block, n - first);
        const std::size_t padded = (m + 3) & ~std::size_t{3}; // batch_block is a multiple of 4
        auto lanes = [&](int slot) {
            return scratch.data() + static_cast<std::size_t>(slot) * batch_block;
        };
        int sp = 0;
        for (const Instruction& in : program.code) {
            switch (in.op) {
            case op_store:
            case op_load: {
                const int from = in.op == op_store ? sp - 1 : in.n;
                const int to = in.op == op_store ? in.n : sp++;
                varying[to] = varying[from];
                if (varying[from])
                    std::copy_n(lanes(from), padded, lanes(to));
                else
                    uniform[to] = uniform[from];
                break;
            }
            case op_const:
                uniform[sp] = in.c, varying[sp++] = false;
                break;
            case op_x:
                std::copy_n(xs + first, m, lanes(sp)), varying[sp++] = true;
                break;
            case op_y:
                uniform[sp] = y, varying[sp++] = false;
                break;
            case op_z:
                uniform[sp] = z, varying[sp++] = false;
                break;
            case op_param:
                uniform[sp] = params[in.n], varying[sp++] = false;
                break;
            case op_add:
            case op_sub:
            case op_mul:
            case op_div:
            case op_pow: {
                const int a = sp - 2, b = sp - 1;
                --sp;
                if (!varying[a] && !varying[b])
                    uniform[a] = apply_binary(in.op, uniform[a], uniform[b]);
                else if (varying[a] && varying[b])
                    binary_lanes(in.op, lanes(a), lanes(b), padded);
                else if (varying[a])
                    binary_lane_value(in.op, lanes(a), uniform[b], padded);
                else
                    binary_value_lane(in.op, uniform[a], lanes(b), lanes(a), padded);
                varying[a] = varying[a] || varying[b];
                break;
            }
            default:
                if (varying[sp - 1])
                    unary_lane(in, lanes(sp - 1), padded);
                else
                    uniform[sp - 1] = apply_instruction(in, uniform[sp - 1]);
                break;
            }
        }
        if (varying[0])
            std::copy_n(lanes(0), m, out + first);
        else
            std::fill_n(out + first, m, uniform[0]);
    }
}

} // namespace isoparm::geom::implicit
