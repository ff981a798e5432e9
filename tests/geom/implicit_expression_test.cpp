// Tests of the implicit-surface expression language: grammar, values, gradients, errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "core/geom/implicit/expression.hpp"

namespace isoparm::geom::implicit {
namespace {

double eval(const std::string& text, glm::dvec3 p = {0.3, -0.7, 1.1},
            const std::vector<std::string>& names = {}, const std::vector<double>& params = {}) {
    auto program = compile(text, names);
    EXPECT_TRUE(program.ok()) << text << ": " << (program ? "" : program.error().message);
    if (!program) return std::nan("");
    return program->value(p, params.empty() ? nullptr : params.data());
}

TEST(ImplicitExpression, NumbersAndVariables) {
    EXPECT_EQ(eval("42"), 42.0);
    EXPECT_EQ(eval("1.5e2"), 150.0);
    EXPECT_EQ(eval("1E-3"), 0.001);
    EXPECT_EQ(eval("2e+2"), 200.0);
    EXPECT_EQ(eval(".5"), 0.5);
    EXPECT_EQ(eval("5."), 5.0);
    EXPECT_EQ(eval("1e-400"), 0.0); // underflows to zero, not an error
    EXPECT_EQ(eval("x", {2, 3, 4}), 2.0);
    EXPECT_EQ(eval("y", {2, 3, 4}), 3.0);
    EXPECT_EQ(eval("z", {2, 3, 4}), 4.0);
    EXPECT_EQ(eval("  x\t+\ny  ", {2, 3, 4}), 5.0);
}

TEST(ImplicitExpression, PrecedenceAndAssociativity) {
    const glm::dvec3 p{3, 2, 5};
    EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
    EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
    EXPECT_EQ(eval("10 - 4 - 3"), 3.0); // left-associative
    EXPECT_EQ(eval("24 / 4 / 2"), 3.0); // left-associative
    EXPECT_EQ(eval("2^3^2"), 512.0);    // right-associative: 2^(3^2)
    EXPECT_EQ(eval("(2^3)^2"), 64.0);
    EXPECT_EQ(eval("-x^2", p), -9.0); // -(x^2)
    EXPECT_EQ(eval("-2^2"), -4.0);
    EXPECT_EQ(eval("(-2)^2"), 4.0);
    EXPECT_EQ(eval("2^-1"), 0.5);
    EXPECT_EQ(eval("x^-1", p), 1.0 / 3.0);
    EXPECT_EQ(eval("2^-x^2", {1, 0, 0}), 0.5); // 2^(-(x^2))
    EXPECT_EQ(eval("--x", p), 3.0);
    EXPECT_EQ(eval("+x", p), 3.0);
    EXPECT_EQ(eval("-+-x", p), 3.0);
    EXPECT_EQ(eval("2 * -x", p), -6.0);
    EXPECT_EQ(eval("x - y * z", p), 3.0 - 10.0);
    EXPECT_EQ(eval("x * y ^ 2", p), 12.0);
    EXPECT_EQ(eval("-x * y", p), -6.0);
    EXPECT_EQ(eval("x / y * z", p), 3.0 / 2.0 * 5.0);
    EXPECT_EQ(eval("2 * x^3 - y", p), 52.0);
}

TEST(ImplicitExpression, EveryFunction) {
    const glm::dvec3 p{0.4, 0.9, 2.5};
    EXPECT_DOUBLE_EQ(eval("sin(x)", p), std::sin(0.4));
    EXPECT_DOUBLE_EQ(eval("cos(x)", p), std::cos(0.4));
    EXPECT_DOUBLE_EQ(eval("tan(x)", p), std::tan(0.4));
    EXPECT_DOUBLE_EQ(eval("exp(y)", p), std::exp(0.9));
    EXPECT_DOUBLE_EQ(eval("log(z)", p), std::log(2.5));
    EXPECT_DOUBLE_EQ(eval("sqrt(z)", p), std::sqrt(2.5));
    EXPECT_DOUBLE_EQ(eval("abs(x - y)", p), 0.5);
    EXPECT_DOUBLE_EQ(eval("sin(2)"), std::sin(2.0)); // folded
    EXPECT_DOUBLE_EQ(eval("sqrt(sin(x)^2 + cos(x)^2)", p), 1.0);
    EXPECT_TRUE(std::isnan(eval("log(-1)")));
    EXPECT_TRUE(std::isnan(eval("sqrt(x)", {-1, 0, 0})));
}

TEST(ImplicitExpression, Powers) {
    const glm::dvec3 p{1.7, -2.3, 0.6};
    EXPECT_DOUBLE_EQ(eval("x^0", p), 1.0);
    EXPECT_DOUBLE_EQ(eval("x^1", p), 1.7);
    EXPECT_DOUBLE_EQ(eval("y^3", p), -2.3 * -2.3 * -2.3);
    EXPECT_DOUBLE_EQ(eval("y^7", p), std::pow(-2.3, 7));
    EXPECT_DOUBLE_EQ(eval("x^-3", p), std::pow(1.7, -3));
    EXPECT_DOUBLE_EQ(eval("x^0.5", p), std::sqrt(1.7));
    EXPECT_DOUBLE_EQ(eval("x^100", p), std::pow(1.7, 100));
    EXPECT_DOUBLE_EQ(eval("x^z", p), std::pow(1.7, 0.6));
    EXPECT_DOUBLE_EQ(eval("2^z", p), std::pow(2.0, 0.6));
    EXPECT_TRUE(std::isnan(eval("y^0.5", p)));
}

TEST(ImplicitExpression, ConstantFolding) {
    auto a = compile("2 * 3 + 1 - 2^3^2 / sin(0)^2");
    ASSERT_TRUE(a.ok());
    EXPECT_EQ(a->instruction_count(), 1u);
    auto b = compile("x^2 + y^2 + z^2 - 1");
    ASSERT_TRUE(b.ok());
    // x, ^2, y, ^2, +, z, ^2, +, -1: powers and constants fuse into their operations.
    EXPECT_EQ(b->instruction_count(), 9u);
}

TEST(ImplicitExpression, Parameters) {
    const std::vector<std::string> names{"a", "b", "radius_2"};
    const std::vector<double> values{2.0, -1.5, 0.25};
    auto program = compile("a*x + b*y - radius_2", names);
    ASSERT_TRUE(program.ok());
    EXPECT_EQ(program->parameter_names(), names);
    EXPECT_DOUBLE_EQ(program->value({1, 2, 3}, values.data()), 2.0 - 3.0 - 0.25);
    glm::dvec3 g;
    program->value_and_gradient({1, 2, 3}, g, values.data());
    EXPECT_EQ(g, glm::dvec3(2.0, -1.5, 0.0));

    auto unknown = compile("a*x + c", names);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().message, "unknown name 'c' at column 7");

    for (const auto& bad :
         std::vector<std::vector<std::string>>{{"x"}, {"sin"}, {"a", "a"}, {"2a"}, {""}, {"a-b"}}) {
        auto p = compile("1", bad);
        ASSERT_FALSE(p.ok());
        EXPECT_EQ(p.error().code, ErrorCode::schema);
        EXPECT_EQ(p.error().path, "/parameters/" + std::to_string(bad.size() - 1));
    }
}

// Central differences with step h have error O(h^2); h = 1e-5 gives ~1e-9 relative.
void expect_gradient_matches(const std::string& text, const glm::dvec3& p,
                             const std::vector<std::string>& names = {},
                             const std::vector<double>& params = {}) {
    auto program = compile(text, names);
    ASSERT_TRUE(program.ok()) << text;
    const double* pv = params.empty() ? nullptr : params.data();
    glm::dvec3 g;
    const double v = program->value_and_gradient(p, g, pv);
    EXPECT_EQ(v, program->value(p, pv)) << text; // the same arithmetic, the same bits
    const double h = 1e-5;
    for (int a = 0; a < 3; ++a) {
        glm::dvec3 lo = p, hi = p;
        lo[a] -= h;
        hi[a] += h;
        const double fd = (program->value(hi, pv) - program->value(lo, pv)) / (2 * h);
        EXPECT_NEAR(g[a], fd, 1e-6 * (1 + std::fabs(fd))) << text << " axis " << a;
    }
}

TEST(ImplicitExpression, GradientsMatchFiniteDifferences) {
    const std::vector<std::string> texts{
        "x^2 + y^2 + z^2 - 1",
        "(x^2 + y^2 + z^2 + 0.36 - 0.0625)^2 - 4 * 0.36 * (x^2 + y^2)",
        "x*y*z - x/y + z/x",
        "sin(x*y) + cos(y - z) * tan(z/3)",
        "exp(-x^2) * log(y^2 + 1) + sqrt(z^2 + 2)",
        "abs(x - y) + abs(z)",
        "x^y + 2^z + z^0.5 + x^-2 + 3/x - 1 - y",
        "-x^3 + (y - 2)^4 / (z + 3)^-1",
        "x^(y*z)",
        "2 - x - (3 - y) * (4 / z) + 5 / (x + y)",
        "a*x^2 + b*y*z - a/b",
    };
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.3, 1.7);
    for (const auto& t : texts)
        for (int k = 0; k < 20; ++k)
            expect_gradient_matches(t, {u(rng), u(rng), u(rng)}, {"a", "b"}, {1.3, -0.4});
}

TEST(ImplicitExpression, ConstantExponentGradientIsFiniteForNegativeBase) {
    // d/dx x^2 at x < 0 must not pick up a log(x) term.
    auto p = compile("x^2 + x^(1+1) + x^3");
    ASSERT_TRUE(p.ok());
    glm::dvec3 g;
    p->value_and_gradient({-2, 0, 0}, g);
    EXPECT_DOUBLE_EQ(g.x, -4.0 - 4.0 + 12.0);
}

TEST(ImplicitExpression, BatchMatchesScalarBitForBit) {
    auto program =
        compile("sin(x*y) + x^3 - 2/x + a*z^0.7 - (x - y)^2 + abs(x) + x^y + (x - 0.5)^4", {"a"});
    ASSERT_TRUE(program.ok());
    const double a = 0.8;
    std::vector<double> xs(1000), out(1000);
    for (std::size_t i = 0; i < xs.size(); ++i) xs[i] = -2.0 + 4.0 * i / 999.0;
    std::vector<double> scratch;
    program->values_along_x(xs.data(), xs.size(), 0.7, 1.3, out.data(), &a, scratch);
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const double expect = program->value({xs[i], 0.7, 1.3}, &a);
        if (std::isnan(expect))
            EXPECT_TRUE(std::isnan(out[i]));
        else
            EXPECT_EQ(out[i], expect) << i;
    }
}

// A random expression over every instruction the compiler emits: variables, parameters and
// constants on either side of each operator (the *_c forms), integer, fractional and variable
// exponents, unary minus and every function.
std::string random_expression(std::mt19937& rng, int depth) {
    auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    if (depth == 0 || pick(4) == 0) {
        static const char* leaves[] = {"x", "y", "z", "a", "b", "0", "1.5", "-2", "0.3", "3"};
        return leaves[pick(10)];
    }
    static const char* functions[] = {"sin", "cos", "tan", "exp", "log", "sqrt", "abs"};
    static const char* exponents[] = {"2", "3", "4", "5", "0", "-1", "-3", "0.5", "1.7", "y", "a"};
    switch (pick(8)) {
    case 0:
        return "(" + random_expression(rng, depth - 1) + " + " + random_expression(rng, depth - 1) +
               ")";
    case 1:
        return "(" + random_expression(rng, depth - 1) + " - " + random_expression(rng, depth - 1) +
               ")";
    case 2:
        return "(" + random_expression(rng, depth - 1) + " * " + random_expression(rng, depth - 1) +
               ")";
    case 3:
        return "(" + random_expression(rng, depth - 1) + " / " + random_expression(rng, depth - 1) +
               ")";
    case 4:
        return "(" + random_expression(rng, depth - 1) + ")^" + exponents[pick(11)];
    case 5:
        return "-(" + random_expression(rng, depth - 1) + ")";
    default:
        return std::string(functions[pick(7)]) + "(" + random_expression(rng, depth - 1) + ")";
    }
}

// Same bits, or both NaN (NaN payloads are not part of the contract).
bool same_bits(double a, double b) {
    return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(ImplicitExpression, BatchDualsMatchOnePointCallsBitForBit) {
    std::mt19937 rng(2024);
    const double params[2] = {0.8, -1.25};
    // Ordinary points, zeros (division by zero, log 0, 0^-1), negatives (log, sqrt, fractional
    // powers: NaN) and large values (overflow to infinity, inf - inf): 270 points, so the
    // 256-point blocks and their padding are crossed.
    std::vector<glm::dvec3> points, directions;
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    for (int k = 0; k < 264; ++k) {
        points.emplace_back(u(rng), u(rng), u(rng));
        directions.emplace_back(u(rng), u(rng), u(rng));
    }
    for (const glm::dvec3 p :
         {glm::dvec3(0, 0, 0), glm::dvec3(0, 1, -1), glm::dvec3(-1, -2, 0),
          glm::dvec3(1e200, -1e200, 3), glm::dvec3(700, 710, -750), glm::dvec3(-0.0, 2, 1e-310)}) {
        points.push_back(p);
        directions.emplace_back(1.0, -0.5, 0.0);
    }
    const std::size_t n = points.size();
    std::vector<double> scratch, values(n), derivatives(n), gvalues(n);
    std::vector<glm::dvec3> gradients(n);
    for (int e = 0; e < 300; ++e) {
        const std::string text = random_expression(rng, 1 + e % 5);
        auto program = compile(text, {"a", "b"});
        ASSERT_TRUE(program.ok()) << text;
        // Counts below the block size, and all of them.
        for (const std::size_t count : {std::size_t{1}, std::size_t{5}, n}) {
            program->values_and_derivatives(points.data(), directions.data(), count, values.data(),
                                            derivatives.data(), params, scratch);
            program->values_and_gradients(points.data(), count, gvalues.data(), gradients.data(),
                                          params, scratch);
            for (std::size_t k = 0; k < count; ++k) {
                double d = 0;
                glm::dvec3 g;
                const double v = program->value_and_derivative(points[k], directions[k], d, params);
                const double vg = program->value_and_gradient(points[k], g, params);
                ASSERT_TRUE(same_bits(values[k], v)) << text << " at point " << k;
                ASSERT_TRUE(same_bits(derivatives[k], d)) << text << " at point " << k;
                ASSERT_TRUE(same_bits(gvalues[k], vg)) << text << " at point " << k;
                for (int i = 0; i < 3; ++i)
                    ASSERT_TRUE(same_bits(gradients[k][i], g[i]))
                        << text << " at point " << k << ", component " << i;
            }
        }
    }
}

// Rows several to a block (values per block, per row and per point mixed in every way the
// random expressions give): the same bits as one point at a time, for rows shorter than a
// block, exactly one, and longer (split across blocks).
TEST(ImplicitExpression, RowBlocksMatchOnePointCallsBitForBit) {
    std::mt19937 rng(77);
    const double params[2] = {0.8, -1.25};
    std::vector<double> ys = {-2.5, -1.0, -0.0, 0.0, 0.3, 1.0, 2.0, 1e200, -3.0};
    std::vector<double> scratch;
    for (int e = 0; e < 200; ++e) {
        const std::string text = random_expression(rng, 1 + e % 5);
        auto program = compile(text, {"a", "b"});
        ASSERT_TRUE(program.ok()) << text;
        for (const std::size_t n : {std::size_t{1}, std::size_t{3}, std::size_t{51},
                                    std::size_t{256}, std::size_t{300}}) {
            std::vector<double> xs(n), out(n * ys.size());
            for (std::size_t i = 0; i < n; ++i) xs[i] = -2.0 + 4.0 * static_cast<double>(i) / n;
            program->values_on_rows(xs.data(), n, ys.data(), ys.size(), 0.7, out.data(), params,
                                    scratch);
            for (std::size_t r = 0; r < ys.size(); ++r)
                for (std::size_t i = 0; i < n; ++i)
                    ASSERT_TRUE(
                        same_bits(out[r * n + i], program->value({xs[i], ys[r], 0.7}, params)))
                        << text << " at row " << r << ", point " << i << " of " << n;
        }
    }
}

struct BadInput {
    std::string text;
    std::string message;
};

TEST(ImplicitExpression, ColumnPreciseErrors) {
    const std::vector<BadInput> cases{
        {"", "unexpected end of expression at column 1"},
        {"   ", "unexpected end of expression at column 4"},
        {"x+", "unexpected end of expression at column 3"},
        {"x^", "unexpected end of expression at column 3"},
        {"(x", "expected ')' at column 3"},
        {"(x y", "expected ')' at column 4"},
        {"sin(x", "expected ')' at column 6"},
        {"x)", "unexpected ')' at column 2"},
        {"x^2 + y^2 - 1)", "unexpected ')' at column 14"},
        {"()", "unexpected ')' at column 2"},
        {"sin()", "unexpected ')' at column 5"},
        {"2..3", "unexpected '.' at column 3"},
        {"1.2.3", "unexpected '.' at column 4"},
        {".", "unexpected '.' at column 1"},
        {"sin x", "expected '(' after 'sin' at column 5"},
        {"sqrt", "expected '(' after 'sqrt' at column 5"},
        {"foo(x)", "unknown function 'foo' at column 1"},
        {"x+q", "unknown name 'q' at column 3"},
        {"x + pi", "unknown name 'pi' at column 5"},
        {"x**2", "unexpected '*' at column 3"},
        {"*x", "unexpected '*' at column 1"},
        {"2x", "unexpected 'x' at column 2"},
        {"x y", "unexpected 'y' at column 3"},
        {"x(2)", "unexpected '(' at column 2"},
        {"x $ y", "unexpected '$' at column 3"},
        {"sin(x, y)", "expected ')' at column 6"},
        {"x \xE2\x88\x92 y", "unexpected '\xE2\x88\x92' at column 3"}, // U+2212 minus sign
        {"\xC3\xA9\xC3\xA9 + )", "unexpected '\xC3\xA9' at column 1"},
        {"1e", "expected digits after the exponent 'e' at column 3"},
        {"1e+", "expected digits after the exponent 'e' at column 4"},
        {"1e999", "number '1e999' is too large for a double at column 1"},
        {"x^2 + (y", "expected ')' at column 9"},
    };
    for (const auto& c : cases) {
        auto p = compile(c.text);
        ASSERT_FALSE(p.ok()) << "'" << c.text << "' compiled";
        EXPECT_EQ(p.error().code, ErrorCode::parse) << c.text;
        EXPECT_EQ(p.error().message, c.message) << c.text;
        EXPECT_EQ(p.error().path, "") << c.text;
    }
}

TEST(ImplicitExpression, DeepNestingIsAnErrorNotACrash) {
    std::string ok_text = std::string(60, '(') + "x" + std::string(60, ')');
    EXPECT_TRUE(compile(ok_text).ok());
    std::string deep = std::string(100000, '(') + "x" + std::string(100000, ')');
    auto p = compile(deep);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().message, "expression nested more than 64 levels deep at column 65");
    std::string tower = "x";
    for (int k = 0; k < 100; ++k) tower += "^x";
    EXPECT_FALSE(compile(tower).ok());
    // Long flat sums and long sign runs need no depth.
    std::string sum = "x";
    for (int k = 0; k < 10000; ++k) sum += "+x";
    auto s = compile(sum);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s->value({1, 0, 0}), 10001.0);
    EXPECT_TRUE(compile(std::string(100000, '-') + "x").ok());
    // Right-nested sums use the stack up to the nesting limit (two levels per '^(').
    std::string right = "";
    for (int k = 0; k < 32; ++k) right += "x+2*x^(";
    right += "x" + std::string(32, ')');
    auto r = compile(right);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(std::isfinite(r->value({0.5, 0, 0})));
}

} // namespace
} // namespace isoparm::geom::implicit
