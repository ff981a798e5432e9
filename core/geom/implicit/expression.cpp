// The expression parser (recursive descent) and its value, batch and dual-number evaluators.
#include "core/geom/implicit/expression.hpp"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace isoparm::geom::implicit {
namespace {

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
};

// Nesting (parentheses, function calls, exponents) is bounded so the parser's recursion and the
// evaluator's fixed-size stack are bounded: each level holds at most three pending operands
// (a sum's left side, a product's left side, a power's base), so the stack stays below 3 * 65 + 1.
constexpr int max_nesting = 64;
constexpr int stack_capacity = 256;
constexpr int max_int_exponent = 64; // larger integer exponents go through pow
constexpr std::size_t batch_block = 256;

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

bool is_small_integer(double c) {
    return std::isfinite(c) && c == std::floor(c) && std::fabs(c) <= max_int_exponent;
}

struct FunctionName {
    const char* name;
    Op op;
};
constexpr FunctionName functions[] = {
    {"sin", op_sin}, {"cos", op_cos},   {"tan", op_tan}, {"exp", op_exp},
    {"log", op_log}, {"sqrt", op_sqrt}, {"abs", op_abs},
};

const FunctionName* find_function(std::string_view name) {
    for (const auto& f : functions)
        if (name == f.name) return &f;
    return nullptr;
}

bool is_name_start(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_name_char(char c) {
    return is_name_start(c) || (c >= '0' && c <= '9');
}
bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

struct Token {
    enum Kind { number, name, plus, minus, star, slash, caret, lparen, rparen, other, end };
    Kind kind = end;
    std::size_t begin = 0; // byte offsets into the text
    std::size_t end_ = 0;
    double value = 0.0;
};

// Thrown inside the parser only; compile() turns it into a geom::Error.
struct ParseFailure {
    std::string message;
};

class Parser {
public:
    Parser(std::string_view text, const std::vector<std::string>& params)
        : text_(text), params_(params) {}

    std::vector<Program::Instruction> run() {
        next();
        parse_expr();
        if (tok_.kind != Token::end) fail_unexpected();
        return std::move(code_);
    }

private:
    // 1-based column of a byte offset, counting UTF-8 code points (continuation bytes skip).
    int column(std::size_t offset) const {
        int col = 1;
        for (std::size_t i = 0; i < offset && i < text_.size(); ++i)
            if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++col;
        return col;
    }
    [[noreturn]] void fail(const std::string& what, std::size_t offset) const {
        throw ParseFailure{what + " at column " + std::to_string(column(offset))};
    }
    std::string token_text(const Token& t) const {
        return std::string(text_.substr(t.begin, t.end_ - t.begin));
    }
    [[noreturn]] void fail_unexpected() const {
        if (tok_.kind == Token::end) fail("unexpected end of expression", tok_.begin);
        fail("unexpected '" + token_text(tok_) + "'", tok_.begin);
    }

    void next() {
        std::size_t i = pos_;
        while (i < text_.size() &&
               (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\n' || text_[i] == '\r'))
            ++i;
        Token t;
        t.begin = i;
        if (i >= text_.size()) {
            t.kind = Token::end;
            t.end_ = i;
        } else if (is_digit(text_[i]) ||
                   (text_[i] == '.' && i + 1 < text_.size() && is_digit(text_[i + 1]))) {
            lex_number(t);
        } else if (is_name_start(text_[i])) {
            std::size_t j = i + 1;
            while (j < text_.size() && is_name_char(text_[j])) ++j;
            t.kind = Token::name;
            t.end_ = j;
        } else {
            t.end_ = i + 1;
            switch (text_[i]) {
            case '+':
                t.kind = Token::plus;
                break;
            case '-':
                t.kind = Token::minus;
                break;
            case '*':
                t.kind = Token::star;
                break;
            case '/':
                t.kind = Token::slash;
                break;
            case '^':
                t.kind = Token::caret;
                break;
            case '(':
                t.kind = Token::lparen;
                break;
            case ')':
                t.kind = Token::rparen;
                break;
            default: {
                // One whole UTF-8 character, so the message shows what the user typed.
                t.kind = Token::other;
                std::size_t j = i + 1;
                while (j < text_.size() && (static_cast<unsigned char>(text_[j]) & 0xC0) == 0x80)
                    ++j;
                t.end_ = j;
            }
            }
        }
        tok_ = t;
        pos_ = t.end_;
    }

    // digits [ '.' digits ] [ ('e' | 'E') [ '+' | '-' ] digits ], or '.' digits [...].
    void lex_number(Token& t) {
        std::size_t i = t.begin;
        while (i < text_.size() && is_digit(text_[i])) ++i;
        if (i < text_.size() && text_[i] == '.') {
            ++i;
            while (i < text_.size() && is_digit(text_[i])) ++i;
        }
        if (i < text_.size() && text_[i] == '.') fail("unexpected '.'", i);
        bool negative_exponent = false;
        if (i < text_.size() && (text_[i] == 'e' || text_[i] == 'E')) {
            std::size_t j = i + 1;
            if (j < text_.size() && (text_[j] == '+' || text_[j] == '-')) {
                negative_exponent = text_[j] == '-';
                ++j;
            }
            if (j >= text_.size() || !is_digit(text_[j]))
                fail("expected digits after the exponent '" + std::string(1, text_[i]) + "'", j);
            while (j < text_.size() && is_digit(text_[j])) ++j;
            i = j;
        }
        t.kind = Token::number;
        t.end_ = i;
        const char* first = text_.data() + t.begin;
        const char* last = text_.data() + i;
        // from_chars is locale-independent, unlike strtod; it does not accept a leading '.'.
        std::string buffer;
        if (*first == '.') {
            buffer.push_back('0');
            buffer.append(first, last);
            first = buffer.data();
            last = buffer.data() + buffer.size();
        }
        auto [ptr, ec] = std::from_chars(first, last, t.value);
        if (ec == std::errc::result_out_of_range) {
            if (!negative_exponent)
                fail("number '" + token_text(t) + "' is too large for a double", t.begin);
            t.value = 0.0; // underflow: the nearest double is zero
        } else if (ec != std::errc() || ptr != last) {
            fail("malformed number '" + token_text(t) + "'", t.begin);
        }
    }

    // expr = term { ('+' | '-') term }
    void parse_expr() {
        std::size_t start = code_.size();
        parse_term();
        while (tok_.kind == Token::plus || tok_.kind == Token::minus) {
            Op op = tok_.kind == Token::plus ? op_add : op_sub;
            next();
            std::size_t rhs = code_.size();
            parse_term();
            emit_binary(op, start, rhs);
        }
    }

    // term = unary { ('*' | '/') unary }
    void parse_term() {
        std::size_t start = code_.size();
        parse_unary();
        while (tok_.kind == Token::star || tok_.kind == Token::slash) {
            Op op = tok_.kind == Token::star ? op_mul : op_div;
            next();
            std::size_t rhs = code_.size();
            parse_unary();
            emit_binary(op, start, rhs);
        }
    }

    // unary = { '+' | '-' } power. Signs apply after '^', so -x^2 = -(x^2).
    void parse_unary() {
        bool negate = false;
        while (tok_.kind == Token::plus || tok_.kind == Token::minus) {
            if (tok_.kind == Token::minus) negate = !negate;
            next();
        }
        std::size_t start = code_.size();
        parse_power();
        if (negate) emit_unary(op_neg, start);
    }

    // power = primary [ '^' unary ]: right-associative (2^3^2 = 2^9), and the exponent may
    // carry a sign (x^-1).
    void parse_power() {
        std::size_t start = code_.size();
        parse_primary();
        if (tok_.kind == Token::caret) {
            std::size_t at = tok_.begin;
            next();
            enter(at);
            std::size_t rhs = code_.size();
            parse_unary();
            --depth_;
            emit_binary(op_pow, start, rhs);
        }
    }

    // primary = number | 'x' | 'y' | 'z' | parameter | function '(' expr ')' | '(' expr ')'
    void parse_primary() {
        switch (tok_.kind) {
        case Token::number:
            push(op_const, 0, tok_.value);
            next();
            return;
        case Token::name: {
            std::string_view name = text_.substr(tok_.begin, tok_.end_ - tok_.begin);
            std::size_t at = tok_.begin;
            next();
            if (const FunctionName* f = find_function(name)) {
                if (tok_.kind != Token::lparen)
                    fail("expected '(' after '" + std::string(name) + "'", tok_.begin);
                next();
                enter(at);
                std::size_t start = code_.size();
                parse_expr();
                expect_rparen();
                --depth_;
                emit_unary(f->op, start);
                return;
            }
            if (name == "x") return push(op_x);
            if (name == "y") return push(op_y);
            if (name == "z") return push(op_z);
            for (std::size_t k = 0; k < params_.size(); ++k)
                if (name == params_[k]) return push(op_param, static_cast<std::int32_t>(k));
            if (tok_.kind == Token::lparen)
                fail("unknown function '" + std::string(name) + "'", at);
            fail("unknown name '" + std::string(name) + "'", at);
        }
        case Token::lparen: {
            enter(tok_.begin);
            next();
            parse_expr();
            expect_rparen();
            --depth_;
            return;
        }
        default:
            fail_unexpected();
        }
    }

    void expect_rparen() {
        if (tok_.kind != Token::rparen) fail("expected ')'", tok_.begin);
        next();
    }

    void enter(std::size_t at) {
        if (++depth_ > max_nesting)
            fail("expression nested more than " + std::to_string(max_nesting) + " levels deep", at);
    }

    void push(Op op, std::int32_t n = 0, double c = 0.0) {
        code_.push_back(Program::Instruction{op, n, c});
    }

    // True when code_[begin, end) is a single constant.
    bool single_const(std::size_t begin, std::size_t end) const {
        return end == begin + 1 && code_[begin].op == op_const;
    }

    // Constant folding uses the evaluator's own arithmetic, so folded and unfolded programs
    // give the same bits.
    void emit_unary(Op op, std::size_t start) {
        if (single_const(start, code_.size())) {
            code_[start].c = apply_unary(op, code_[start].c);
            return;
        }
        push(op);
    }

    void emit_binary(Op op, std::size_t lhs, std::size_t rhs) {
        const bool lc = single_const(lhs, rhs);
        const bool rc = single_const(rhs, code_.size());
        if (lc && rc) {
            double v = op == op_pow && is_small_integer(code_[rhs].c)
                           ? powi(code_[lhs].c, static_cast<int>(code_[rhs].c))
                           : apply_binary(op, code_[lhs].c, code_[rhs].c);
            code_.resize(lhs);
            push(op_const, 0, v);
            return;
        }
        if (rc) {
            double c = code_.back().c;
            code_.pop_back();
            switch (op) {
            case op_add:
                return push(op_add_c, 0, c);
            case op_sub:
                return push(op_sub_c, 0, c);
            case op_mul:
                return push(op_mul_c, 0, c);
            case op_div:
                return push(op_div_c, 0, c);
            default:
                if (is_small_integer(c)) return push(op_pow_int, static_cast<std::int32_t>(c), c);
                return push(op_pow_c, 0, c);
            }
        }
        if (lc && op != op_pow) {
            double c = code_[lhs].c;
            code_.erase(code_.begin() + static_cast<std::ptrdiff_t>(lhs));
            switch (op) {
            case op_add:
                return push(op_add_c, 0, c); // c + a == a + c exactly
            case op_sub:
                return push(op_rsub_c, 0, c);
            case op_mul:
                return push(op_mul_c, 0, c);
            default:
                return push(op_rdiv_c, 0, c);
            }
        }
        push(op);
    }

    std::string_view text_;
    const std::vector<std::string>& params_;
    std::size_t pos_ = 0;
    Token tok_;
    int depth_ = 0;
    std::vector<Program::Instruction> code_;
};

// Stack effect of one instruction.
int stack_delta(std::uint8_t op) {
    switch (op) {
    case op_const:
    case op_x:
    case op_y:
    case op_z:
    case op_param:
        return 1;
    case op_add:
    case op_sub:
    case op_mul:
    case op_div:
    case op_pow:
        return -1;
    default:
        return 0;
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

void binary_lanes(std::uint8_t op, double* __restrict a, const double* __restrict b,
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

void binary_lane_value(std::uint8_t op, double* __restrict a, double b, std::size_t m) {
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

void binary_value_lane(std::uint8_t op, double a, const double* __restrict b,
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

void unary_lane(const Program::Instruction& in, double* __restrict a, std::size_t m) {
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
    auto scale = [&](double k) {
        for (int i = 0; i < L; ++i) end[-1].d[i] *= k;
    };
    for (const Program::Instruction& in : code) {
        switch (in.op) {
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
        case op_add: {
            const Dual<N>& r = *--end;
            for (int i = 0; i < L; ++i) end[-1].d[i] += r.d[i];
            end[-1].v += r.v;
            break;
        }
        case op_sub: {
            const Dual<N>& r = *--end;
            for (int i = 0; i < L; ++i) end[-1].d[i] -= r.d[i];
            end[-1].v -= r.v;
            break;
        }
        case op_mul: {
            const Dual<N>& r = *--end;
            for (int i = 0; i < L; ++i) end[-1].d[i] = end[-1].d[i] * r.v + end[-1].v * r.d[i];
            end[-1].v *= r.v;
            break;
        }
        case op_div: {
            const Dual<N>& r = *--end;
            const double v = end[-1].v / r.v;
            for (int i = 0; i < L; ++i) end[-1].d[i] = (end[-1].d[i] - v * r.d[i]) / r.v;
            end[-1].v = v;
            break;
        }
        case op_pow: {
            // d(a^b) = b a^(b-1) da + a^b log(a) db; the log term only where b varies, so a
            // constant exponent does not turn the derivative into NaN for a <= 0.
            const Dual<N>& r = *--end;
            const double v = std::pow(end[-1].v, r.v);
            const double da = r.v * std::pow(end[-1].v, r.v - 1.0);
            bool varies = false;
            for (int i = 0; i < L; ++i) varies = varies || r.d[i] != 0.0;
            const double db = varies ? v * std::log(end[-1].v) : 0.0;
            for (int i = 0; i < L; ++i)
                end[-1].d[i] = end[-1].d[i] * da + (varies ? r.d[i] * db : 0.0);
            end[-1].v = v;
            break;
        }
        case op_add_c:
            end[-1].v += in.c;
            break;
        case op_sub_c:
            end[-1].v -= in.c;
            break;
        case op_rsub_c:
            end[-1].v = in.c - end[-1].v;
            scale(-1.0);
            break;
        case op_mul_c:
            end[-1].v *= in.c;
            scale(in.c);
            break;
        case op_div_c:
            end[-1].v /= in.c;
            for (int i = 0; i < L; ++i) end[-1].d[i] /= in.c;
            break;
        case op_rdiv_c: {
            const double v = in.c / end[-1].v;
            scale(-v / end[-1].v);
            end[-1].v = v;
            break;
        }
        case op_pow_int:
            if (in.n == 2) {
                scale(2.0 * end[-1].v);
                end[-1].v = end[-1].v * end[-1].v;
            } else {
                scale(in.n == 0 ? 0.0 : in.n * powi(end[-1].v, in.n - 1));
                end[-1].v = powi(end[-1].v, in.n);
            }
            break;
        case op_pow_c:
            scale(in.c * std::pow(end[-1].v, in.c - 1.0));
            end[-1].v = std::pow(end[-1].v, in.c);
            break;
        case op_neg:
            end[-1].v = -end[-1].v;
            scale(-1.0);
            break;
        case op_sin:
            scale(std::cos(end[-1].v));
            end[-1].v = std::sin(end[-1].v);
            break;
        case op_cos:
            scale(-std::sin(end[-1].v));
            end[-1].v = std::cos(end[-1].v);
            break;
        case op_tan: {
            const double t = std::tan(end[-1].v);
            scale(1.0 + t * t);
            end[-1].v = t;
            break;
        }
        case op_exp: {
            const double e = std::exp(end[-1].v);
            scale(e);
            end[-1].v = e;
            break;
        }
        case op_log:
            scale(1.0 / end[-1].v);
            end[-1].v = std::log(end[-1].v);
            break;
        case op_sqrt: {
            const double r = std::sqrt(end[-1].v);
            scale(0.5 / r);
            end[-1].v = r;
            break;
        }
        case op_abs:
            // The derivative of |a| is sign(a), and 0 at a = 0 (a subgradient).
            scale(end[-1].v > 0 ? 1.0 : (end[-1].v < 0 ? -1.0 : 0.0));
            end[-1].v = std::fabs(end[-1].v);
            break;
        default:
            assert(false && "unknown opcode");
        }
    }
    assert(end == stack + 1);
    for (int i = 0; i < N; ++i) tangent[i] = stack[0].d[i];
    return stack[0].v;
}

// The batch form of evaluate_dual: each stack slot holds a value lane and lanes_for<N> tangent
// lanes of up to dual_block points, so an instruction is dispatched once per block instead of
// once per point. Every lane does exactly evaluate_dual's arithmetic in the same order (the
// padding tangent of N = 3 included: a NaN there makes op_pow take its log term, and the
// batch must do the same), so each point gets the same bits as a call of its own. The loops
// are small functions with __restrict arguments so that GCC's -O2 vectorizes them (lambdas'
// captured pointers lose the no-alias promise).
constexpr std::size_t dual_block = 64;

template <int N> struct DualLanes {
    static constexpr int L = lanes_for<N>;
    double* v;
    double* d[L];
};

template <int N> std::size_t dual_scratch_size(int max_stack) {
    // The slots, then one lane of per-point factors.
    return (static_cast<std::size_t>(max_stack) * (1 + lanes_for<N>)+1) * dual_block;
}

// d = d * bv + av * bd (the product rule, with a's old value).
void product_tangent(double* __restrict d, const double* __restrict bv, const double* __restrict av,
                     const double* __restrict bd, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = d[k] * bv[k] + av[k] * bd[k]; });
}

// d = (d - q * bd) / bv (the quotient rule, q the new value).
void quotient_tangent(double* __restrict d, const double* __restrict q, const double* __restrict bd,
                      const double* __restrict bv, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = (d[k] - q[k] * bd[k]) / bv[k]; });
}

// std::fill_n is not vectorized at -O2 (an unknown trip count); four lanes a step are.
void fill_lane(double* __restrict d, double c, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] = c; });
}

void scale_lane(double* __restrict d, const double* __restrict f, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] *= f[k]; });
}

void scale_lane(double* __restrict d, double f, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] *= f; });
}

void divide_lane(double* __restrict d, double f, std::size_t m) {
    for_lanes(m, [=](std::size_t k) { d[k] /= f; });
}

// directions: the tangent seeds of x, y, z per point (N = 1); nullptr: unit seeds (N = 3).
template <int N>
void evaluate_dual_lanes(const std::vector<Program::Instruction>& code, int max_stack,
                         const glm::dvec3* points, const glm::dvec3* directions, std::size_t m,
                         const double* params, double* scratch, double* values, double* tangents) {
    constexpr int L = lanes_for<N>;
    const std::size_t padded = (m + 3) & ~std::size_t{3}; // dual_block is a multiple of 4
    auto slot = [&](int s) {
        DualLanes<N> lanes;
        double* base = scratch + static_cast<std::size_t>(s) * (1 + L) * dual_block;
        lanes.v = base;
        for (int i = 0; i < L; ++i) lanes.d[i] = base + (1 + i) * dual_block;
        return lanes;
    };
    int sp = 0;
    double* const f = scratch + static_cast<std::size_t>(max_stack) * (1 + L) * dual_block;
    // The per-point factors f of evaluate_dual's scale(), then the tangents scaled by them.
    auto scale_all = [&](const DualLanes<N>& a) {
        for (int i = 0; i < L; ++i) scale_lane(a.d[i], f, padded);
    };
    for (const Program::Instruction& in : code) {
        switch (in.op) {
        case op_const:
        case op_param: {
            const DualLanes<N> a = slot(sp++);
            fill_lane(a.v, in.op == op_const ? in.c : params[in.n], padded);
            for (int i = 0; i < L; ++i) fill_lane(a.d[i], 0.0, padded);
            break;
        }
        case op_x:
        case op_y:
        case op_z: {
            const DualLanes<N> a = slot(sp++);
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
        case op_sub: {
            --sp;
            const DualLanes<N> a = slot(sp - 1), b = slot(sp);
            for (int i = 0; i < L; ++i) binary_lanes(in.op, a.d[i], b.d[i], padded);
            binary_lanes(in.op, a.v, b.v, padded);
            break;
        }
        case op_mul: {
            --sp;
            const DualLanes<N> a = slot(sp - 1), b = slot(sp);
            for (int i = 0; i < L; ++i) product_tangent(a.d[i], b.v, a.v, b.d[i], padded);
            binary_lanes(op_mul, a.v, b.v, padded);
            break;
        }
        case op_div: {
            --sp;
            const DualLanes<N> a = slot(sp - 1), b = slot(sp);
            binary_lanes(op_div, a.v, b.v, padded);
            for (int i = 0; i < L; ++i) quotient_tangent(a.d[i], a.v, b.d[i], b.v, padded);
            break;
        }
        case op_pow: {
            --sp;
            const DualLanes<N> a = slot(sp - 1), b = slot(sp);
            for (std::size_t k = 0; k < padded; ++k) {
                const double v = std::pow(a.v[k], b.v[k]);
                const double da = b.v[k] * std::pow(a.v[k], b.v[k] - 1.0);
                bool varies = false;
                for (int i = 0; i < L; ++i) varies = varies || b.d[i][k] != 0.0;
                const double db = varies ? v * std::log(a.v[k]) : 0.0;
                for (int i = 0; i < L; ++i)
                    a.d[i][k] = a.d[i][k] * da + (varies ? b.d[i][k] * db : 0.0);
                a.v[k] = v;
            }
            break;
        }
        default: {
            const DualLanes<N> a = slot(sp - 1);
            double* const v = a.v;
            const double c = in.c;
            switch (in.op) {
            case op_add_c:
            case op_sub_c:
                unary_lane(in, v, padded);
                break;
            case op_rsub_c:
            case op_neg:
                unary_lane(in, v, padded);
                for (int i = 0; i < L; ++i) scale_lane(a.d[i], -1.0, padded);
                break;
            case op_mul_c:
                unary_lane(in, v, padded);
                for (int i = 0; i < L; ++i) scale_lane(a.d[i], c, padded);
                break;
            case op_div_c:
                unary_lane(in, v, padded);
                for (int i = 0; i < L; ++i) divide_lane(a.d[i], c, padded);
                break;
            case op_rdiv_c:
                for (std::size_t k = 0; k < padded; ++k) {
                    const double r = c / v[k];
                    f[k] = -r / v[k];
                    v[k] = r;
                }
                scale_all(a);
                break;
            case op_pow_int:
                if (in.n == 2) {
                    for_lanes(padded, [=](std::size_t k) { f[k] = 2.0 * v[k]; });
                } else {
                    const int n = in.n;
                    for (std::size_t k = 0; k < padded; ++k)
                        f[k] = n == 0 ? 0.0 : n * powi(v[k], n - 1);
                }
                scale_all(a);
                unary_lane(in, v, padded);
                break;
            case op_pow_c:
                for (std::size_t k = 0; k < padded; ++k) {
                    f[k] = c * std::pow(v[k], c - 1.0);
                    v[k] = std::pow(v[k], c);
                }
                scale_all(a);
                break;
            case op_sin:
                for (std::size_t k = 0; k < padded; ++k) {
                    f[k] = std::cos(v[k]);
                    v[k] = std::sin(v[k]);
                }
                scale_all(a);
                break;
            case op_cos:
                for (std::size_t k = 0; k < padded; ++k) {
                    f[k] = -std::sin(v[k]);
                    v[k] = std::cos(v[k]);
                }
                scale_all(a);
                break;
            case op_tan:
                for (std::size_t k = 0; k < padded; ++k) {
                    const double t = std::tan(v[k]);
                    f[k] = 1.0 + t * t;
                    v[k] = t;
                }
                scale_all(a);
                break;
            case op_exp:
                for (std::size_t k = 0; k < padded; ++k) f[k] = v[k] = std::exp(v[k]);
                scale_all(a);
                break;
            case op_log:
                for (std::size_t k = 0; k < padded; ++k) {
                    f[k] = 1.0 / v[k];
                    v[k] = std::log(v[k]);
                }
                scale_all(a);
                break;
            case op_sqrt:
                for (std::size_t k = 0; k < padded; ++k) {
                    const double r = std::sqrt(v[k]);
                    f[k] = 0.5 / r;
                    v[k] = r;
                }
                scale_all(a);
                break;
            case op_abs:
                for (std::size_t k = 0; k < padded; ++k) {
                    f[k] = v[k] > 0 ? 1.0 : (v[k] < 0 ? -1.0 : 0.0);
                    v[k] = std::fabs(v[k]);
                }
                scale_all(a);
                break;
            default:
                assert(false && "unknown opcode");
            }
            break;
        }
        }
    }
    assert(sp == 1);
    const DualLanes<N> top = slot(0);
    for (std::size_t k = 0; k < m; ++k) {
        values[k] = top.v[k];
        for (int i = 0; i < N; ++i) tangents[k * N + i] = top.d[i][k];
    }
}

} // namespace

Expected<Program> compile(std::string_view text, const std::vector<std::string>& parameter_names) {
    for (std::size_t k = 0; k < parameter_names.size(); ++k) {
        const std::string& name = parameter_names[k];
        const std::string path = "/parameters/" + std::to_string(k);
        bool identifier = !name.empty() && is_name_start(name[0]) &&
                          std::all_of(name.begin(), name.end(), is_name_char);
        if (!identifier)
            return make_error(ErrorCode::schema,
                              "parameter name '" + name +
                                  "' is not a name (a letter or '_', then letters, digits, '_')",
                              path);
        if (name == "x" || name == "y" || name == "z" || find_function(name))
            return make_error(ErrorCode::schema,
                              "parameter name '" + name +
                                  "' is reserved (x, y, z and function names cannot be parameters)",
                              path);
        if (std::find(parameter_names.begin(), parameter_names.begin() + k, name) !=
            parameter_names.begin() + k)
            return make_error(ErrorCode::schema,
                              "parameter name '" + name + "' is given more than once", path);
    }
    Program program;
    try {
        program.code_ = Parser(text, parameter_names).run();
    } catch (const ParseFailure& e) {
        return make_error(ErrorCode::parse, e.message);
    }
    program.parameter_names_ = parameter_names;
    int depth = 0;
    for (const auto& in : program.code_) {
        depth += stack_delta(in.op);
        program.max_stack_ = std::max(program.max_stack_, depth);
    }
    assert(depth == 1 && program.max_stack_ <= stack_capacity);
    return program;
}

double Program::value(const glm::dvec3& p, const double* params) const {
    assert(params != nullptr || parameter_names_.empty());
    double s[stack_capacity];
    int sp = 0;
    for (const Instruction& in : code_) {
        switch (in.op) {
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

double Program::value_and_gradient(const glm::dvec3& p, glm::dvec3& gradient,
                                   const double* params) const {
    assert(params != nullptr || parameter_names_.empty());
    static constexpr double seeds[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    double tangent[3];
    const double v = evaluate_dual<3>(code_, p, seeds, params, tangent);
    gradient = glm::dvec3(tangent[0], tangent[1], tangent[2]);
    return v;
}

double Program::value_and_derivative(const glm::dvec3& p, const glm::dvec3& direction,
                                     double& derivative, const double* params) const {
    assert(params != nullptr || parameter_names_.empty());
    const double seeds[3][1] = {{direction.x}, {direction.y}, {direction.z}};
    double tangent[1];
    const double v = evaluate_dual<1>(code_, p, seeds, params, tangent);
    derivative = tangent[0];
    return v;
}

void Program::values_along_x(const double* xs, std::size_t n, double y, double z, double* out,
                             const double* params, std::vector<double>& scratch) const {
    assert(params != nullptr || parameter_names_.empty());
    const std::size_t need = static_cast<std::size_t>(max_stack_) * batch_block;
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
        for (const Instruction& in : code_) {
            switch (in.op) {
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

void Program::values_and_derivatives(const glm::dvec3* points, const glm::dvec3* directions,
                                     std::size_t n, double* values, double* derivatives,
                                     const double* params, std::vector<double>& scratch) const {
    assert(params != nullptr || parameter_names_.empty());
    const std::size_t need = dual_scratch_size<1>(max_stack_);
    if (scratch.size() < need) scratch.resize(need);
    for (std::size_t first = 0; first < n; first += dual_block) {
        const std::size_t m = std::min(dual_block, n - first);
        const glm::dvec3* dirs = directions + first;
        evaluate_dual_lanes<1>(code_, max_stack_, points + first, dirs, m, params, scratch.data(),
                               values + first, derivatives + first);
    }
}

void Program::values_and_gradients(const glm::dvec3* points, std::size_t n, double* values,
                                   glm::dvec3* gradients, const double* params,
                                   std::vector<double>& scratch) const {
    assert(params != nullptr || parameter_names_.empty());
    const std::size_t need = dual_scratch_size<3>(max_stack_);
    if (scratch.size() < need) scratch.resize(need);
    double tangents[dual_block * 3];
    for (std::size_t first = 0; first < n; first += dual_block) {
        const std::size_t m = std::min(dual_block, n - first);
        evaluate_dual_lanes<3>(code_, max_stack_, points + first, nullptr, m, params,
                               scratch.data(), values + first, tangents);
        for (std::size_t k = 0; k < m; ++k)
            gradients[first + k] =
                glm::dvec3(tangents[k * 3], tangents[k * 3 + 1], tangents[k * 3 + 2]);
    }
}

} // namespace isoparm::geom::implicit
