// Out of memory is an error, not an abort. Under `ulimit -v` every run
// that hit the cap used to end in SIGABRT: nlohmann::json's destructor allocates while the
// first std::bad_alloc unwinds. These tests run the protocol and the scene loader in a child
// process under RLIMIT_AS; a child killed by a signal fails the test.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <malloc.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/json/out_of_memory.hpp"
#include "core/protocol/protocol.hpp"
#include "core/scene/scene_io.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool address_sanitizer = true;
#else
constexpr bool address_sanitizer = false;
#endif
#else
constexpr bool address_sanitizer = false;
#endif

// The address space this process uses now, in bytes.
std::size_t address_space_in_use() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0;
    statm >> pages;
    return pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

struct ChildResult {
    bool exited = false; // false: killed by a signal (the old SIGABRT)
    int status = -1;
    std::string output;
};

// Runs `body` in a fresh child process whose address space may grow by `headroom` bytes
// (beyond the memory reserve, out_of_memory.hpp); what the body
// returns is its exit status and what it writes to the given stream comes back as `output`.
ChildResult run_limited(std::size_t headroom, const std::function<int(std::ostream&)>& body) {
    // In the freshly executed copy (below): run the body under the limit and report.
    if (const char* report = std::getenv("ISOPARM_OOM_REPORT")) {
        std::ostringstream out;
        ::malloc_trim(0);
        // The reserve first, so `headroom` is what the work itself gets.
        isoparm::json_io::arm_memory_reserve();
        const std::size_t cap = address_space_in_use() + headroom;
        const rlimit limit{cap, cap};
        if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(100);
        const int status = body(out);
        std::ofstream(report, std::ios::binary) << out.str();
        ::_exit(status);
    }
    // A forked child would inherit the heap this process freed (tens of MB after the other
    // tests), where the work could run without the address space growing at all; so the child
    // executes this test binary afresh, running only the current test, which comes back here.
    char name[] = "/tmp/isoparm-oom-XXXXXX";
    const int fd = ::mkstemp(name);
    if (fd < 0) return {};
    ::close(fd);
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string filter =
        std::string("--gtest_filter=") + test->test_suite_name() + "." + test->name();
    const pid_t child = ::fork();
    if (child == 0) {
        ::setenv("ISOPARM_OOM_REPORT", name, 1);
        ::execl("/proc/self/exe", "/proc/self/exe", filter.c_str(), static_cast<char*>(nullptr));
        ::_exit(101);
    }
    ChildResult r;
    int status = 0;
    if (child > 0 && ::waitpid(child, &status, 0) == child) {
        r.exited = WIFEXITED(status);
        r.status = r.exited ? WEXITSTATUS(status) : WTERMSIG(status);
    }
    std::ifstream in(name, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    r.output = text.str();
    std::remove(name);
    return r;
}

std::string bicubic_tessellation(int samples) {
    json points = json::array();
    for (int i = 0; i < 4; ++i) {
        json row = json::array();
        for (int j = 0; j < 4; ++j) row.push_back({i, j, (i * j) % 3});
        points.push_back(row);
    }
    return json{{"op", "tessellate"},
                {"surface", {{"type", "bezier"}, {"degree", {3, 3}}, {"points", points}}},
                {"samples", {samples, samples}}}
        .dump();
}

const std::string small_request =
    R"({"op": "basis", "degree": 2, "knots": [0,0,0,1,1,1], "param": 0.5})";

constexpr std::size_t mib = std::size_t{1} << 20;

TEST(OutOfMemory, ReleaseJsonEmptiesATreeWithoutChangingItsType) {
    json tree = json::parse(R"({"a": [1, [2, [3, {"b": [4]}]]], "c": "text"})");
    isoparm::json_io::release_json(tree);
    EXPECT_TRUE(tree.is_object());
    EXPECT_TRUE(tree.empty());
}

TEST(OutOfMemory, ARequestThatRunsOutIsALimitErrorNotAnAbort) {
    if (address_sanitizer) GTEST_SKIP() << "RLIMIT_AS and AddressSanitizer do not mix";
    // A 1000 x 1000 tessellation needs its mesh alone (~75 MB) and more; give it 50 MB.
    const std::string request = bicubic_tessellation(1000);
    const ChildResult r = run_limited(50 * mib, [&](std::ostream& out) {
        std::ostringstream err;
        return isoparm::protocol::run_protocol_text(request, out, err);
    });
    ASSERT_TRUE(r.exited) << "killed by signal " << r.status;
    EXPECT_EQ(r.status, 1);
    const json answer = json::parse(r.output);
    EXPECT_EQ(answer["ok"], false);
    EXPECT_EQ(answer["error"]["code"], "limit");
    EXPECT_NE(answer["error"]["message"].get<std::string>().find("memory"), std::string::npos);
}

// Answers other than meshes and evaluations are still built as JSON trees: running out while
// building one is the case nlohmann's allocating destructor turned into SIGABRT. de Boor's
// trace on a degree-30 x 4096-point surface: 2 million points, ~390 MB as a tree.
TEST(OutOfMemory, RunningOutWhileBuildingAnAnswerTreeIsALimitError) {
    if (address_sanitizer) GTEST_SKIP() << "RLIMIT_AS and AddressSanitizer do not mix";
    const int p = 30, n_v = 4096;
    json points = json::array();
    for (int i = 0; i <= p; ++i) {
        json row = json::array();
        for (int j = 0; j < n_v; ++j) row.push_back({i, j * 0.001, (i * j) % 5});
        points.push_back(row);
    }
    json knots_u = json::array(), knots_v = {0.0, 0.0};
    for (int k = 0; k <= p; ++k) knots_u.push_back(0.0);
    for (int k = 0; k <= p; ++k) knots_u.push_back(1.0);
    for (int k = 1; k < n_v - 1; ++k) knots_v.push_back(static_cast<double>(k) / (n_v - 1));
    knots_v.push_back(1.0);
    knots_v.push_back(1.0);
    const json request = {{"op", "deboor"},
                          {"surface",
                           {{"type", "bspline"},
                            {"degree", {p, 1}},
                            {"knots", {knots_u, knots_v}},
                            {"points", points}}},
                          {"u", 0.5},
                          {"v", 0.5}};
    const std::string text = request.dump();
    const ChildResult r = run_limited(100 * mib, [&](std::ostream& out) {
        std::ostringstream err;
        return isoparm::protocol::run_protocol_text(text, out, err);
    });
    ASSERT_TRUE(r.exited) << "killed by signal " << r.status;
    EXPECT_EQ(r.status, 1);
    const json answer = json::parse(r.output);
    EXPECT_EQ(answer["error"]["code"], "limit");
}

TEST(OutOfMemory, ABatchContinuesAfterAnElementRunsOut) {
    if (address_sanitizer) GTEST_SKIP() << "RLIMIT_AS and AddressSanitizer do not mix";
    const std::string batch = "[" + bicubic_tessellation(1000) + ", " + small_request + ", " +
                              bicubic_tessellation(1000) + ", " + small_request + "]";
    const ChildResult r = run_limited(50 * mib, [&](std::ostream& out) {
        std::ostringstream err;
        return isoparm::protocol::run_protocol_text(batch, out, err);
    });
    ASSERT_TRUE(r.exited) << "killed by signal " << r.status;
    EXPECT_EQ(r.status, 1);
    const json answers = json::parse(r.output);
    ASSERT_EQ(answers.size(), 4u);
    EXPECT_EQ(answers[0]["error"]["code"], "limit");
    EXPECT_EQ(answers[1]["ok"], true);
    EXPECT_EQ(answers[2]["error"]["code"], "limit"); // the reserve was set aside again
    EXPECT_EQ(answers[3]["ok"], true);
}

TEST(OutOfMemory, ParsingAHugeInputThatRunsOutIsALimitError) {
    if (address_sanitizer) GTEST_SKIP() << "RLIMIT_AS and AddressSanitizer do not mix";
    // 24 MB of text, ~12 million values (below the reader's cap of 2^24): the tree alone needs
    // ~200 MB, and nlohmann's destructor would need another 16 bytes per element to free it.
    std::string text = "[0";
    text.reserve(24 * mib);
    while (text.size() < 24 * mib) text += ",0";
    text += "]";
    const ChildResult r = run_limited(150 * mib, [&](std::ostream& out) {
        std::ostringstream err;
        return isoparm::protocol::run_protocol_text(std::move(text), out, err);
    });
    ASSERT_TRUE(r.exited) << "killed by signal " << r.status;
    EXPECT_EQ(r.status, 1);
    const json answer = json::parse(r.output);
    EXPECT_EQ(answer["error"]["code"], "limit");
}

// One 600 x 600 B-spline surface: ~13 MB of text, far more once parsed.
void write_big_scene(const fs::path& file) {
    const int n = 600;
    std::string knots = "[0, 0, 0, 0";
    for (int k = 1; k <= n - 4; ++k) knots += ", " + std::to_string(k);
    for (int k = 0; k < 4; ++k) knots += ", " + std::to_string(n - 3);
    knots += "]";
    std::string points = "[";
    for (int i = 0; i < n; ++i) {
        points += i ? ", [" : "[";
        for (int j = 0; j < n; ++j)
            points +=
                (j ? ", [" : "[") + std::to_string(i) + ".5, " + std::to_string(j) + ".25, 0.125]";
        points += "]";
    }
    points += "]";
    std::ofstream(file, std::ios::binary)
        << R"({"format": "isoparm-scene", "version": 1, "objects": [{"id": 1, )"
        << R"("name": "big", "kind": "surface", "surface": {"type": "bspline", )"
        << R"("degree": [3, 3], "knots": [)" << knots << ", " << knots << R"(], "points": )"
        << points << "}}]}";
}

// The limited part of the scene test, in a freshly executed copy of this test binary: a forked
// child inherits the heap this process freed (tens of MB after the other tests), where the
// scene would load without the address space growing at all.
[[noreturn]] void load_scene_under_limit(const std::string& scene, const std::string& report) {
    isoparm::json_io::arm_memory_reserve();
    const std::size_t cap = address_space_in_use() + 30 * mib;
    const rlimit limit{cap, cap};
    if (::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(100);
    const auto doc = isoparm::scene::load_scene(scene);
    if (doc) ::_exit(2); // the limit did not bite: the test would prove nothing
    std::ofstream(report) << doc.error().message;
    ::_exit(doc.error().code == isoparm::geom::ErrorCode::limit ? 0 : 3);
}

TEST(OutOfMemory, LoadingASceneThatRunsOutIsALimitError) {
    if (address_sanitizer) GTEST_SKIP() << "RLIMIT_AS and AddressSanitizer do not mix";
    if (const char* scene = std::getenv("ISOPARM_OOM_SCENE"))
        load_scene_under_limit(scene, std::getenv("ISOPARM_OOM_REPORT"));
    // One name for this test and the copies of it that run_limited executes.
    const char* inherited = std::getenv("ISOPARM_OOM_STEM");
    const std::string stem =
        inherited
            ? std::string(inherited)
            : (fs::temp_directory_path() / ("isoparm-oom-scene-" + std::to_string(::getpid())))
                  .string();
    ::setenv("ISOPARM_OOM_STEM", stem.c_str(), 1);
    const std::string file = stem + ".json", report = stem + ".txt";
    constexpr std::size_t unlimited = std::size_t{1} << 40;
    const ChildResult written = run_limited(unlimited, [&](std::ostream&) {
        write_big_scene(file);
        return isoparm::scene::load_scene(file) ? 0 : 1;
    });
    ASSERT_TRUE(written.exited && written.status == 0) << "the scene itself must be valid";
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::setenv("ISOPARM_OOM_SCENE", file.c_str(), 1);
        ::setenv("ISOPARM_OOM_REPORT", report.c_str(), 1);
        ::execl("/proc/self/exe", "/proc/self/exe",
                "--gtest_filter=OutOfMemory.LoadingASceneThatRunsOutIsALimitError",
                static_cast<char*>(nullptr));
        ::_exit(101);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    std::ifstream in(report);
    std::stringstream message;
    message << in.rdbuf();
    fs::remove(file);
    fs::remove(report);
    ::unsetenv("ISOPARM_OOM_STEM");
    ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 0) << message.str();
    EXPECT_NE(message.str().find("not enough memory"), std::string::npos) << message.str();
}

} // namespace
