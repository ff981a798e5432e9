// Common-subexpression elimination for the expression language's postfix code (value
// numbering by hash-consing, as in Aho, Lam, Sethi & Ullman, "Compilers", 6.1.2: the DAG of an
// expression). The gallery's surfaces repeat their scaled coordinates many times (the Clebsch
// cubic has ((x + 4)/1.3) seventeen times); computed once, they cost one copy each.
#include <cstdint>
#include <cstring>
#include <map>
#include <tuple>
#include <vector>

#include "core/geom/implicit/expression_ops.hpp"

namespace isoparm::geom::implicit::detail {
namespace {

using Instruction = Program::Instruction;

// Operands of an instruction of folded code: 2 for the binary ones, 0 for pushes, else 1.
int operand_count(std::uint8_t op) {
    return is_binary(op) ? 2 : stack_delta(op) == 1 ? 0 : 1;
}

// A subexpression's identity: its instruction (opcode and immediates, the constant by its bits)
// and its operands' identities.
using Key = std::tuple<std::uint8_t, std::int32_t, std::uint64_t, int, int>;

} // namespace

std::vector<Instruction> share_subexpressions(const std::vector<Instruction>& code, int max_stack,
                                              int& slots) {
    // Value numbers: id[e] names the subexpression that ends at instruction e; start[e] is
    // where it begins. refs counts the uses of each value number in the DAG (a repeated
    // subexpression's own operands are counted once, at its first occurrence).
    const std::size_t n = code.size();
    std::vector<int> id(n), start(n), refs;
    std::map<Key, int> numbers;
    std::vector<std::pair<int, int>> stack; // (value number, start)
    for (std::size_t e = 0; e < n; ++e) {
        const Instruction& in = code[e];
        const int arity = operand_count(in.op);
        int a = -1, b = -1, begin = static_cast<int>(e);
        if (arity == 2) {
            b = stack.back().first;
            stack.pop_back();
        }
        if (arity >= 1) {
            a = stack.back().first;
            begin = stack.back().second;
            stack.pop_back();
        }
        std::uint64_t bits = 0;
        std::memcpy(&bits, &in.c, sizeof bits);
        const auto [it, fresh] =
            numbers.try_emplace(Key{in.op, in.n, bits, a, b}, static_cast<int>(refs.size()));
        if (fresh) {
            refs.push_back(0);
            if (a >= 0) ++refs[a];
            if (b >= 0) ++refs[b];
        }
        id[e] = it->second;
        start[e] = begin;
        stack.emplace_back(it->second, begin);
    }

    // Emit in the original order. The first occurrence of a value used more than once (and not
    // a single push, which costs no more than a load) is stored to a register; a later
    // occurrence has been emitted as it was met, and is then cut back to one load (postfix code
    // keeps a subexpression's instructions together at the end of the output).
    std::vector<int> reg(refs.size(), -1);
    std::vector<std::size_t> out_at(n); // output length before instruction e
    std::vector<Instruction> out;
    out.reserve(n);
    int next_slot = max_stack;
    for (std::size_t e = 0; e < n; ++e) {
        out_at[e] = out.size();
        const int v = id[e];
        if (reg[v] >= 0) {
            out.resize(out_at[static_cast<std::size_t>(start[e])]);
            out.push_back(Instruction{op_load, reg[v], 0.0});
            continue;
        }
        out.push_back(code[e]);
        if (refs[v] > 1 && operand_count(code[e].op) > 0 && next_slot < stack_capacity) {
            reg[v] = next_slot++;
            out.push_back(Instruction{op_store, reg[v], 0.0});
        }
    }
    slots = next_slot;
    return out;
}

} // namespace isoparm::geom::implicit::detail
