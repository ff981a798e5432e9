// The protocol's JSON reader (duplicates, depth, overflow) and writer (shortest round trip).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>

#include "core/json/reader.hpp"
#include "core/json/writer.hpp"

namespace {

using isoparm::json_io::format_double;
using isoparm::json_io::read_json;
using isoparm::json_io::to_json_text;
using nlohmann::json;

TEST(JsonWrite, FormatsLikeTheReference) {
    EXPECT_EQ(format_double(0.5), "0.5");
    EXPECT_EQ(format_double(1.0), "1.0");
    EXPECT_EQ(format_double(100.0), "100.0");
    EXPECT_EQ(format_double(-2.5), "-2.5");
    EXPECT_EQ(format_double(-0.0), "0.0");
    EXPECT_EQ(format_double(0.0), "0.0");
    EXPECT_EQ(format_double(1e15), "1000000000000000.0");
    EXPECT_EQ(format_double(1e16), "1e+16");
    EXPECT_EQ(format_double(1.5e16), "1.5e+16");
    EXPECT_EQ(format_double(0.0001), "0.0001");
    EXPECT_EQ(format_double(1e-5), "1e-05");
    EXPECT_EQ(format_double(-1.2345e-7), "-1.2345e-07");
    EXPECT_EQ(format_double(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(format_double(5e-324), "5e-324");
    EXPECT_EQ(format_double(1.7976931348623157e308), "1.7976931348623157e+308");
    EXPECT_EQ(format_double(0.8155999999999999), "0.8155999999999999");
}

TEST(JsonWrite, RoundTripsRandomDoubles) {
    std::mt19937_64 rng(12345);
    std::uniform_int_distribution<std::uint64_t> bits;
    int checked = 0;
    while (checked < 20000) {
        const std::uint64_t b = bits(rng);
        double x;
        std::memcpy(&x, &b, sizeof x);
        if (!std::isfinite(x) || x == 0.0) continue;
        const std::string s = format_double(x);
        EXPECT_EQ(std::strtod(s.c_str(), nullptr), x) << s;
        // A JSON reader sees a float, never an integer.
        EXPECT_TRUE(json::parse(s).is_number_float()) << s;
        ++checked;
    }
}

TEST(JsonWrite, IntegersStayIntegersAndOkComesFirst) {
    const json j = {
        {"points", json::array({json::array({1.0, 2.0, 3.0})})}, {"first_index", 3}, {"ok", true}};
    EXPECT_EQ(to_json_text(j), R"({"ok": true, "points": [[1.0, 2.0, 3.0]], "first_index": 3})");
    EXPECT_EQ(to_json_text(json{{"error", {{"path", "/a"}, {"code", "x"}, {"message", "m\"q"}}},
                                {"ok", false}}),
              R"({"ok": false, "error": {"code": "x", "message": "m\"q", "path": "/a"}})");
}

TEST(JsonRead, OverflowingNumbersBecomeInfinities) {
    auto r = read_json(R"({"s": "1e999 \" 1e999", "w": [1e999, 2, -1E+400, 1e-999, 0.5]})");
    ASSERT_TRUE(r.ok()) << r.error().message;
    EXPECT_TRUE(r->problems.empty());
    const json& v = r->value;
    EXPECT_EQ(v["s"], "1e999 \" 1e999");
    EXPECT_TRUE(std::isinf(v["w"][0].get<double>()) && v["w"][0].get<double>() > 0);
    EXPECT_EQ(v["w"][1], 2);
    EXPECT_TRUE(std::isinf(v["w"][2].get<double>()) && v["w"][2].get<double>() < 0);
    EXPECT_EQ(v["w"][3].get<double>(), 0.0); // underflow is just zero
    EXPECT_EQ(v["w"][4].get<double>(), 0.5);
}

TEST(JsonRead, DuplicateKeysAreProblemsWithEscapedPaths) {
    auto r = read_json(R"({"a/b": {"x~": 1, "x~": {"deep": [1, 2]}}, "z": [{"k": 1, "k": 2}]})");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->problems.size(), 2u);
    EXPECT_EQ(r->problems[0].path, "/a~1b/x~0");
    EXPECT_EQ(r->problems[1].path, "/z/0/k");
    EXPECT_EQ(r->value["a/b"]["x~"], 1); // the first value is kept
    const auto under = isoparm::json_io::problems_under(r->problems, "/z");
    ASSERT_EQ(under.size(), 1u);
    EXPECT_EQ(under[0].path, "/0/k");
}

TEST(JsonRead, DepthLimitIsExact) {
    const int limit = isoparm::json_io::max_json_depth;
    auto ok = read_json(std::string(limit, '[') + std::string(limit, ']'));
    ASSERT_TRUE(ok.ok());
    EXPECT_TRUE(ok->problems.empty());
    auto deep = read_json(std::string(limit + 1, '[') + std::string(limit + 1, ']'));
    ASSERT_TRUE(deep.ok());
    ASSERT_EQ(deep->problems.size(), 1u);
    EXPECT_EQ(deep->problems[0].code, isoparm::geom::ErrorCode::limit);
}

TEST(JsonRead, SyntaxErrorsNameLineAndColumn) {
    auto r = read_json("{\n  \"a\": [1,\n  2,,]\n}");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, isoparm::geom::ErrorCode::parse);
    EXPECT_NE(r.error().message.find("line 3, column"), std::string::npos) << r.error().message;
    // An overflow next to a syntax error keeps the position of the error.
    auto o = read_json("[1e999, 1e999 x]");
    ASSERT_FALSE(o.ok());
    EXPECT_NE(o.error().message.find("column 15"), std::string::npos) << o.error().message;
    EXPECT_FALSE(read_json("").ok());
    EXPECT_FALSE(read_json("[1] [2]").ok());
    EXPECT_FALSE(read_json("{\"a\": \"\xff\"}").ok()); // invalid UTF-8
}

} // namespace
