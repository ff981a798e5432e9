// Behaviour identity: the protocol's answer to every request we ship or test with, and every
// scene's bytes after a load and a save, are held in tests/identity/recorded. A change that is
// meant to leave behaviour alone (moving code between modules, merging helpers) must leave these
// byte-identical. A deliberate change re-records them:
//   ISOPARM_RECORD_IDENTITY=1 build/tests/isoparm_core_tests --gtest_filter='Identity.*'
// and the diff of tests/identity/recorded is then part of the change, for review.
#include <gtest/gtest.h>

#include <charconv>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "core/protocol/protocol.hpp"
#include "core/scene/scene_io.hpp"

namespace {

namespace fs = std::filesystem;
using namespace isoparm;

const fs::path source_dir = ISOPARM_SOURCE_DIR;
const fs::path recorded_dir = source_dir / "tests" / "identity" / "recorded";

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

bool recording() {
    const char* v = std::getenv("ISOPARM_RECORD_IDENTITY");
    return v != nullptr && *v != '\0' && std::string(v) != "0";
}

// (group, file) for every regular file in `dir` whose name ends with `suffix`, sorted.
std::vector<std::pair<std::string, fs::path>> inputs(const std::string& group, const fs::path& dir,
                                                     const std::string& suffix) {
    std::vector<std::pair<std::string, fs::path>> out;
    if (!fs::is_directory(dir)) return out;
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        if (e.is_regular_file() && name.size() >= suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0)
            out.emplace_back(group, e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr bool sanitized_build = true;
#else
constexpr bool sanitized_build = false;
#endif

// Under the sanitizers the compiler rounds some floating-point sums differently (a tessellated
// normal's last bit): there the texts must agree except for numbers within 1e-14 relative of
// each other. The normal build holds the recordings byte for byte.
bool same_up_to_last_bits(const std::string& a, const std::string& b) {
    std::size_t i = 0, j = 0;
    // A number at k, read with from_chars (no strtod: under ASan it measures the rest of the
    // string for every number, which is quadratic on a megabyte answer). Nothing for "---".
    auto number_at = [](const std::string& s, std::size_t& k, double& x) {
        if (k >= s.size() || !(std::isdigit(static_cast<unsigned char>(s[k])) || s[k] == '-'))
            return false;
        const auto [end, ec] = std::from_chars(s.data() + k, s.data() + s.size(), x);
        if (ec != std::errc{}) return false;
        k = static_cast<std::size_t>(end - s.data());
        return true;
    };
    while (i < a.size() && j < b.size()) {
        std::size_t i2 = i, j2 = j;
        double x = 0, y = 0;
        if (number_at(a, i2, x) && number_at(b, j2, y)) {
            if (std::abs(x - y) > 1e-14 * std::max({1.0, std::abs(x), std::abs(y)})) return false;
            i = i2;
            j = j2;
            continue;
        }
        if (a[i++] != b[j++]) return false;
    }
    return i == a.size() && j == b.size();
}

// Compares `actual` with the recorded file, or records it.
void check_or_record(const fs::path& recorded, const std::string& actual) {
    if (recording()) {
        fs::create_directories(recorded.parent_path());
        std::ofstream(recorded, std::ios::binary) << actual;
        return;
    }
    ASSERT_TRUE(fs::exists(recorded)) << recorded << " is not recorded (see this file's header)";
    const std::string expected = slurp(recorded);
    if (expected == actual) return;
    if (sanitized_build && same_up_to_last_bits(expected, actual)) return;
    size_t at = 0;
    while (at < expected.size() && at < actual.size() && expected[at] == actual[at]) ++at;
    const size_t from = at > 80 ? at - 80 : 0;
    ADD_FAILURE() << recorded.filename() << " differs at byte " << at << "\n  recorded: ..."
                  << expected.substr(from, 200) << "\n  now:      ..." << actual.substr(from, 200);
}

std::string stem_of(const fs::path& p) {
    std::string name = p.filename().string();
    for (const char* suffix : {".request.json", ".json"}) {
        const std::string s = suffix;
        if (name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0)
            return name.substr(0, name.size() - s.size());
    }
    return name;
}

TEST(Identity, ProtocolAnswers) {
    std::vector<std::pair<std::string, fs::path>> all;
    for (auto group : {inputs("examples", source_dir / "tests/protocol/examples", ".request.json"),
                       inputs("requests", source_dir / "assets/requests", ".json"),
                       inputs("regression", source_dir / "tests/fuzz/regressions/protocol", "")})
        all.insert(all.end(), group.begin(), group.end());
    ASSERT_GT(all.size(), 60u);
    for (const auto& [group, path] : all) {
        SCOPED_TRACE(path.string());
        std::ostringstream out, err;
        const int status = protocol::run_protocol_text(slurp(path), out, err);
        const std::string answer = "exit " + std::to_string(status) + "\n--- stdout\n" + out.str() +
                                   "--- stderr\n" + err.str();
        check_or_record(recorded_dir / "protocol" / (group + "__" + stem_of(path) + ".txt"),
                        answer);
    }
}

TEST(Identity, SceneBytesAfterLoadAndSave) {
    std::vector<std::pair<std::string, fs::path>> all;
    for (auto group : {inputs("scenes", source_dir / "assets/scenes", ".json"),
                       inputs("seed", source_dir / "tests/fuzz/seeds/scene", ""),
                       inputs("regression", source_dir / "tests/fuzz/regressions/scene", "")})
        all.insert(all.end(), group.begin(), group.end());
    ASSERT_GT(all.size(), 15u);
    for (const auto& [group, path] : all) {
        SCOPED_TRACE(path.string());
        const auto loaded = scene::scene_from_text(slurp(path));
        const std::string saved =
            loaded ? scene::scene_to_text(*loaded)
                   : "error " + std::string(geom::name_of(loaded.error().code)) + " at \"" +
                         loaded.error().path + "\": " + loaded.error().message + "\n";
        check_or_record(recorded_dir / "scenes" / (group + "__" + stem_of(path) + ".txt"), saved);
    }
}

} // namespace

namespace {

// The sanitizer builds' comparison: numbers within 1e-14 relative, everything else exact, in
// time linear in the answer's length.
TEST(Identity, LastBitsComparisonReadsNumbersAndText) {
    EXPECT_TRUE(same_up_to_last_bits("exit 0\n--- stdout\n[1.0000000000000002, -3]",
                                     "exit 0\n--- stdout\n[1.0, -3]"));
    EXPECT_FALSE(same_up_to_last_bits("[1.0001]", "[1.0]"));
    EXPECT_FALSE(same_up_to_last_bits("--- stdout", "--- stderr"));
    EXPECT_FALSE(same_up_to_last_bits("[1.0, 2.0]", "[1.0]"));
    std::string big = "exit 0\n--- stdout\n[";
    for (int k = 0; k < 200000; ++k) big += "0.1234567890123456, ";
    big += "1]";
    std::string other = big;
    other[other.size() - 2] = '2';
    EXPECT_TRUE(same_up_to_last_bits(big, big));
    EXPECT_FALSE(same_up_to_last_bits(big, other));
}

} // namespace
