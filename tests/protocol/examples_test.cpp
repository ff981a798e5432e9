// Conformance: every worked example of the shared spec, answered by protocol::handle_request and
// by the text path (run_protocol), compared as the examples' README prescribes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/geom/evaluate.hpp"
#include "core/geom/knots.hpp"
#include "core/json/shapes.hpp"
#include "core/protocol/protocol.hpp"

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace isoparm;

// The worked examples travel with the tests (tests/protocol/examples, a copy of the shared
// spec's), so a clone with nothing beside it tests itself. Where the shared spec is present
// too, its examples that the copy lacks or holds differently are run as well.
const fs::path own_examples = fs::path(ISOPARM_SOURCE_DIR) / "tests" / "protocol" / "examples";
const fs::path shared_examples = fs::path(ISOPARM_SPEC_DIR) / "examples";

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The example stems of one folder ("0001-evaluate-valid"), sorted.
std::vector<std::string> stems_in(const fs::path& dir) {
    std::vector<std::string> stems;
    if (!fs::is_directory(dir)) return stems;
    const std::string suffix = ".request.json";
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (name.size() > suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
            stems.push_back(name.substr(0, name.size() - suffix.size()));
    }
    std::sort(stems.begin(), stems.end());
    return stems;
}

// Every example to run: the request's path without ".request.json".
std::vector<std::string> example_stems() {
    std::vector<std::string> out;
    for (const std::string& stem : stems_in(own_examples))
        out.push_back((own_examples / stem).string());
    for (const std::string& stem : stems_in(shared_examples)) {
        const fs::path mine = own_examples / stem;
        const bool same = fs::exists(mine.string() + ".request.json") &&
                          slurp(mine.string() + ".request.json") ==
                              slurp((shared_examples / stem).string() + ".request.json") &&
                          slurp(mine.string() + ".response.json") ==
                              slurp((shared_examples / stem).string() + ".response.json");
        if (!same) out.push_back((shared_examples / stem).string());
    }
    return out;
}

// The largest |number| anywhere in v: the size of the control net (and of the knots).
double magnitude(const json& v) {
    if (v.is_number()) return std::abs(v.get<double>());
    double m = 0;
    if (v.is_array() || v.is_object())
        for (const json& e : v) m = std::max(m, magnitude(e));
    return m;
}

// Structure identical, numbers within 1e-9 relative to max(scale, |expected|).
void expect_close(const json& expected, const json& actual, double scale, const std::string& at) {
    if (expected.is_number()) {
        ASSERT_TRUE(actual.is_number()) << at << ": expected a number, got " << actual.dump();
        const double e = expected.get<double>(), a = actual.get<double>();
        const double tol = 1e-9 * std::max(scale, std::abs(e));
        EXPECT_LE(std::abs(e - a), tol) << at << ": expected " << e << ", got " << a;
        return;
    }
    ASSERT_EQ(expected.type(), actual.type())
        << at << ": expected " << expected.dump().substr(0, 200) << ", got "
        << actual.dump().substr(0, 200);
    if (expected.is_array()) {
        ASSERT_EQ(expected.size(), actual.size()) << at << ": array lengths differ";
        for (std::size_t i = 0; i < expected.size(); ++i)
            expect_close(expected[i], actual[i], scale, at + "/" + std::to_string(i));
    } else if (expected.is_object()) {
        for (const auto& [key, value] : expected.items()) {
            ASSERT_TRUE(actual.contains(key)) << at << ": missing member '" << key << "'";
            expect_close(value, actual[key], scale, at + "/" + key);
        }
        for (const auto& [key, value] : actual.items()) {
            (void)value;
            EXPECT_TRUE(expected.contains(key)) << at << ": unexpected member '" << key << "'";
        }
    } else {
        EXPECT_EQ(expected, actual) << at;
    }
}

// Clamped in the direction the request works on (elevation and split have one right answer
// only then; convention 5).
bool clamped_in_direction(const json& request) {
    if (request.contains("curve")) {
        auto c = json_io::curve_from_json(request["curve"]);
        return c && geom::is_clamped(c->knots, c->degree, c->count());
    }
    auto s = json_io::surface_from_json(request["surface"]);
    if (!s) return true;
    const geom::Dir d = request.value("direction", "u") == "u" ? geom::Dir::u : geom::Dir::v;
    return geom::is_clamped(s->knots(d), s->degree(d), s->count(d));
}

// Same type, degree, domain and shape (sampled) for two results of an unclamped request.
void expect_same_shape(const json& expected, const json& actual, bool surface, double scale,
                       const std::string& at) {
    ASSERT_EQ(expected["type"], actual["type"]) << at;
    ASSERT_EQ(expected["degree"], actual["degree"]) << at;
    const double tol = 1e-9 * std::max(1.0, scale);
    if (!surface) {
        auto e = json_io::curve_from_json(expected);
        auto a = json_io::curve_from_json(actual);
        ASSERT_TRUE(e.ok()) << at << ": reference curve invalid: " << e.error().message;
        ASSERT_TRUE(a.ok()) << at << ": our curve invalid: " << a.error().message;
        const geom::Interval de = geom::domain(*e);
        const geom::Interval da = geom::domain(*a);
        EXPECT_NEAR(de.lo, da.lo, tol) << at;
        EXPECT_NEAR(de.hi, da.hi, tol) << at;
        for (int k = 0; k <= 40; ++k) {
            const double t = de.lo + (de.hi - de.lo) * k / 40.0;
            auto pe = geom::curve_point(*e, t);
            auto pa = geom::curve_point(*a, std::clamp(t, da.lo, da.hi));
            ASSERT_EQ(pe.has_value(), pa.has_value()) << at << " t=" << t;
            if (pe) {
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR((*pe)[c], (*pa)[c], 1e-8 * std::max(1.0, scale))
                        << at << " t=" << t;
            }
        }
        return;
    }
    auto e = json_io::surface_from_json(expected);
    auto a = json_io::surface_from_json(actual);
    ASSERT_TRUE(e.ok()) << at << ": reference surface invalid: " << e.error().message;
    ASSERT_TRUE(a.ok()) << at << ": our surface invalid: " << a.error().message;
    const geom::Interval eu = geom::domain(*e, geom::Dir::u);
    const geom::Interval ev = geom::domain(*e, geom::Dir::v);
    const geom::Interval au = geom::domain(*a, geom::Dir::u);
    const geom::Interval av = geom::domain(*a, geom::Dir::v);
    EXPECT_NEAR(eu.lo, au.lo, tol) << at;
    EXPECT_NEAR(eu.hi, au.hi, tol) << at;
    EXPECT_NEAR(ev.lo, av.lo, tol) << at;
    EXPECT_NEAR(ev.hi, av.hi, tol) << at;
    for (int i = 0; i <= 12; ++i) {
        for (int j = 0; j <= 12; ++j) {
            const double u = eu.lo + (eu.hi - eu.lo) * i / 12.0;
            const double v = ev.lo + (ev.hi - ev.lo) * j / 12.0;
            auto pe = geom::surface_point(*e, u, v);
            auto pa =
                geom::surface_point(*a, std::clamp(u, au.lo, au.hi), std::clamp(v, av.lo, av.hi));
            ASSERT_EQ(pe.has_value(), pa.has_value()) << at << " u=" << u << " v=" << v;
            if (pe) {
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR((*pe)[c], (*pa)[c], 1e-8 * std::max(1.0, scale))
                        << at << " u=" << u << " v=" << v;
            }
        }
    }
}

void expect_matches(const json& request, const json& expected, const json& actual) {
    ASSERT_TRUE(actual.contains("ok")) << actual.dump().substr(0, 300);
    ASSERT_EQ(expected["ok"], actual["ok"]) << "response: " << actual.dump().substr(0, 400);
    if (!expected["ok"].get<bool>()) {
        const json& e = expected["error"];
        const json& a = actual["error"];
        EXPECT_EQ(e["code"], a["code"]) << "message: " << a.value("message", "");
        EXPECT_EQ(e.contains("path"), a.contains("path"));
        if (e.contains("path")) {
            EXPECT_EQ(e["path"], a.value("path", json())) << a.value("message", "");
        }
        EXPECT_TRUE(a.contains("message") && a["message"].is_string() &&
                    !a["message"].get<std::string>().empty());
        return;
    }
    const double scale = std::max(1.0, magnitude(request));
    const std::string op = request.value("op", "");
    if ((op == "elevate_degree" || op == "split") && !clamped_in_direction(request)) {
        const bool surface = request.contains("surface");
        if (op == "split") {
            ASSERT_EQ(actual["pieces"].size(), 2u);
            for (int k = 0; k < 2; ++k)
                expect_same_shape(expected["pieces"][k], actual["pieces"][k], surface, scale,
                                  "/pieces/" + std::to_string(k));
        } else {
            const char* key = surface ? "surface" : "curve";
            expect_same_shape(expected[key], actual[key], surface, scale, std::string("/") + key);
        }
        return;
    }
    expect_close(expected, actual, scale, "");
}

class SpecExample : public ::testing::TestWithParam<std::string> {};

TEST_P(SpecExample, HandleRequestMatchesTheReference) {
    const std::string stem = GetParam();
    const json request = json::parse(slurp(stem + ".request.json"));
    const json expected = json::parse(slurp(stem + ".response.json"));
    expect_matches(request, expected, protocol::handle_request(request));
}

TEST_P(SpecExample, TextPathGivesTheSameAnswerAndExitStatus) {
    const std::string stem = GetParam();
    const std::string text = slurp(stem + ".request.json");
    const json request = json::parse(text);
    const json expected = json::parse(slurp(stem + ".response.json"));
    std::istringstream in(text);
    std::ostringstream out, err;
    const int status = protocol::run_protocol(in, out, err);
    EXPECT_EQ(status, expected["ok"].get<bool>() ? 0 : 1);
    EXPECT_TRUE(err.str().empty()) << err.str();
    const json actual = json::parse(out.str());
    expect_matches(request, expected, actual);
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
    const fs::path p(info.param);
    std::string s = p.filename().string();
    std::replace(s.begin(), s.end(), '-', '_');
    // A shared example that the copy lacks or holds differently keeps its own name.
    return (p.parent_path() == own_examples ? "e" : "shared_") + s;
}

INSTANTIATE_TEST_SUITE_P(Examples, SpecExample, ::testing::ValuesIn(example_stems()), test_name);

TEST(ExamplesDirectory, HasItsOwnCopyOfTheExamples) {
    // Guards against a moved folder silently running zero examples.
    EXPECT_GE(stems_in(own_examples).size(), 50u) << own_examples;
}

} // namespace
