// The implicit-surface expression language: compile once, evaluate f and grad f fast.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/geom/status.hpp"

namespace isoparm::geom::implicit {

// Numbers, x y z, + - * / ^ (right-associative, binds tighter than unary minus), parentheses,
// sin cos tan exp log sqrt abs, and named parameters (e.g. a, b, c) whose values are given
// at evaluation time. Errors are `parse` with a message that names the column (1-based),
// e.g. "unexpected ')' at column 14". The grammar is in docs/implicit.md.
class Program {
public:
    // f(x, y, z) with the given parameter values (same order as the names given to compile).
    double value(const glm::dvec3& p, const double* params = nullptr) const;
    // f and grad f together.
    double value_and_gradient(const glm::dvec3& p, glm::dvec3& gradient,
                              const double* params = nullptr) const;
    // f and its derivative along direction (grad f . direction), cheaper than the gradient.
    double value_and_derivative(const glm::dvec3& p, const glm::dvec3& direction,
                                double& derivative, const double* params = nullptr) const;
    const std::vector<std::string>& parameter_names() const { return parameter_names_; }

    // Batch form for grid sampling: out[i] = f(xs[i], y, z) for i < n, bit-identical to value().
    // scratch is resized on first use and can be reused across calls (no allocation once warm).
    void values_along_x(const double* xs, std::size_t n, double y, double z, double* out,
                        const double* params, std::vector<double>& scratch) const;
    // Several rows of a layer: out[r * n + i] = f(xs[i], ys[r], z) for r < rows, i < n, the
    // same bits. Short rows are evaluated several to a block (dispatch paid once per block).
    void values_on_rows(const double* xs, std::size_t n, const double* ys, std::size_t rows,
                        double z, double* out, const double* params,
                        std::vector<double>& scratch) const;

    // Batch forms of value_and_derivative and value_and_gradient (the polygonizer refines all
    // the edges of a layer together): for i < n, the same bits as the one-point calls. scratch
    // as for values_along_x.
    void values_and_derivatives(const glm::dvec3* points, const glm::dvec3* directions,
                                std::size_t n, double* values, double* derivatives,
                                const double* params, std::vector<double>& scratch) const;
    void values_and_gradients(const glm::dvec3* points, std::size_t n, double* values,
                              glm::dvec3* gradients, const double* params,
                              std::vector<double>& scratch) const;

    // Number of instructions after constant folding (for tests, diagnostics and the work
    // budget), before repeated subexpressions are shared.
    std::size_t instruction_count() const { return plain_.code.size(); }

    // Repeated subexpressions are computed once and reused (on by default); off, every
    // occurrence is computed again, as before. Either way every result has the same bits
    // (tests and the benchmark compare the two).
    void share_subexpressions(bool on) { sharing_ = on; }
    // Instructions the evaluators run (fewer than instruction_count() when something repeats).
    std::size_t shared_instruction_count() const { return shared_.code.size(); }

    // One stack-machine instruction: an opcode and its immediate (a constant, an integer
    // exponent or a parameter index). Internal; public only so helpers in the .cpp can see it.
    struct Instruction {
        std::uint8_t op = 0;
        std::int32_t n = 0;
        double c = 0.0;
    };

private:
    friend Expected<Program> compile(std::string_view, const std::vector<std::string>&);
    // Postfix code and the stack slots it needs: the operand stack's depth, then the
    // registers that hold shared subexpressions (slots [max_stack, slots)).
    struct Code {
        std::vector<Instruction> code;
        int max_stack = 0;
        int slots = 0;
        bool has_pow = false; // op_pow: a power with a varying exponent
    };
    const Code& run() const { return sharing_ ? shared_ : plain_; }
    Code plain_;  // as parsed and folded
    Code shared_; // repeated subexpressions stored once and loaded (op_store / op_load)
    bool sharing_ = true;
    std::vector<std::string> parameter_names_;
};

// Names not in parameter_names and not x, y, z are errors. Column-precise `parse` errors
// (path ""; the protocol reports them under "/implicit"). Bad parameter names (not an
// identifier, x/y/z, a function name, or a duplicate) are `schema` at "/parameters/<i>".
Expected<Program> compile(std::string_view text,
                          const std::vector<std::string>& parameter_names = {});

} // namespace isoparm::geom::implicit
