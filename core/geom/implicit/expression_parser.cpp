// The expression parser: tokens, recursive descent with constant folding, and compile().
#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

#include "core/geom/implicit/expression.hpp"
#include "core/geom/implicit/expression_ops.hpp"

namespace isoparm::geom::implicit {
namespace {

using namespace detail;

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
    Program::Code& plain = program.plain_;
    try {
        plain.code = Parser(text, parameter_names).run();
    } catch (const ParseFailure& e) {
        return make_error(ErrorCode::parse, e.message);
    }
    program.parameter_names_ = parameter_names;
    int depth = 0;
    for (const auto& in : plain.code) {
        depth += stack_delta(in.op);
        plain.max_stack = std::max(plain.max_stack, depth);
    }
    assert(depth == 1 && plain.max_stack <= stack_capacity);
    plain.slots = plain.max_stack;
    plain.has_pow = std::any_of(plain.code.begin(), plain.code.end(),
                                [](const Program::Instruction& in) { return in.op == op_pow; });
    // The shared code never needs a deeper stack (a load stands for a whole subexpression), so
    // its registers can start where the plain code's stack ends.
    Program::Code& shared = program.shared_;
    shared.code = share_subexpressions(plain.code, plain.max_stack, shared.slots);
    shared.max_stack = plain.max_stack;
    shared.has_pow = plain.has_pow;
    return program;
}

} // namespace isoparm::geom::implicit
