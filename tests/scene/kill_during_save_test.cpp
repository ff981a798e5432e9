// Saving survives being killed: a forked child saves a large scene in a loop and is SIGKILLed
// at random moments; the scene file is always one complete document, old or new.
#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <random>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "core/scene/scene_io.hpp"

using namespace isoparm;
using namespace isoparm::doc;
using namespace isoparm::scene;
namespace fs = std::filesystem;

namespace {

// Big enough that a save takes a while (a 450 x 450 surface is 21 MB of text), so kills land
// inside it; small enough that the whole test takes a few seconds. Sanitizers make formatting
// and parsing several times slower: there a quarter of the size still takes a while to save.
#if defined(__SANITIZE_ADDRESS__)
constexpr int grid_size = 200;
#else
constexpr int grid_size = 450;
#endif
constexpr int kills = 16;

// The default scene plus a grid_size x grid_size surface whose heights depend on `variant`,
// so every variant saves as a different text.
Document big_document(int variant) {
    Document doc = default_document();
    Object o;
    o.id = doc.allocate_id();
    o.name = "terrain";
    geom::Surface s = make_planar_grid(grid_size, grid_size, 3, 3, geom::SplineType::nurbs);
    for (int i = 0; i < s.n_u; ++i)
        for (int j = 0; j < s.n_v; ++j) {
            s.point(i, j).z = 0.1 * std::sin(0.37 * i + 0.11 * j + variant);
            s.weight(i, j) = 1.0 + 0.25 * std::cos(0.05 * i * j + variant);
        }
    o.shape = SurfaceObject{std::move(s)};
    doc.objects.push_back(std::move(o));
    return doc;
}

std::string read_file(const std::string& path) {
    std::string text;
    if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
        char buf[1 << 16];
        for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, f)) > 0;) text.append(buf, n);
        std::fclose(f);
    }
    return text;
}

std::vector<std::string> entries(const fs::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
    std::sort(out.begin(), out.end());
    return out;
}

struct RemoveOnExit {
    fs::path dir;
    ~RemoveOnExit() {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
};

// Drains the child's reports: one 'y' per completed save, 'n' for a save that failed.
void drain(int fd, int& saved, int& failed) {
    char buf[256];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n <= 0) return; // EOF (the child is gone) or EAGAIN
        for (ssize_t k = 0; k < n; ++k) (buf[k] == 'y' ? saved : failed)++;
    }
}

} // namespace

TEST(KillDuringSave, SceneIsAlwaysOneCompleteDocument) {
    const fs::path dir = fs::temp_directory_path() / ("isoparm-kill-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const RemoveOnExit cleanup{dir};
    const std::string target = (dir / "scene.json").string();

    // Variant 0 is on disk before the first child starts; children save 1 and 2 in turn.
    const std::vector<Document> docs = {big_document(0), big_document(1), big_document(2)};
    std::vector<std::string> texts;
    for (const Document& d : docs) texts.push_back(scene_to_text(d));
    ASSERT_GT(texts[0].size(), std::size_t(grid_size) * grid_size * 80) << "a large scene";
    // Every text the file may hold loads as its document: byte equality below then means the
    // file loads and equals that document.
    for (std::size_t k = 0; k < docs.size(); ++k) {
        auto back = scene_from_text(texts[k]);
        ASSERT_TRUE(back.ok()) << back.error().message;
        ASSERT_TRUE(same_document(*back, docs[k])) << "variant " << k;
    }
    // One save, timed: kills at any moment are spread over about two saves.
    const auto start = std::chrono::steady_clock::now();
    ASSERT_TRUE(save_scene(docs[0], target).ok());
    const auto save_us = std::max<long>(1000, std::chrono::duration_cast<std::chrono::microseconds>(
                                                  std::chrono::steady_clock::now() - start)
                                                  .count());

    std::mt19937 rng(20240609);
    int mid_write = 0, saved = 0, failed = 0;
    std::string stray; // the temporary file the last kill left, if any
    for (int kill = 0; kill < kills; ++kill) {
        int pipe_fds[2];
        ASSERT_EQ(::pipe(pipe_fds), 0);
        const pid_t child = ::fork();
        ASSERT_GE(child, 0) << std::strerror(errno);
        if (child == 0) {
            // The child: save until killed (dies with the test runner if that goes first).
            ::prctl(PR_SET_PDEATHSIG, SIGKILL);
            ::close(pipe_fds[0]);
            for (int k = 0; k < 1000; ++k) {
                const char report = save_scene(docs[1 + k % 2], target).ok() ? 'y' : 'n';
                (void)!::write(pipe_fds[1], &report, 1);
            }
            ::_exit(0);
        }
        ::close(pipe_fds[1]);
        const std::string tmp = target + ".tmp-" + std::to_string(child);
        // Odd kills wait until the child is writing its temporary file, so some kills surely
        // land in the middle of the write; even kills come at any moment of the save loop.
        if (kill % 2 == 1) {
            const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
            while (!fs::exists(tmp) && std::chrono::steady_clock::now() < give_up)
                std::this_thread::sleep_for(std::chrono::microseconds(100));
            std::this_thread::sleep_for(std::chrono::microseconds(
                std::uniform_int_distribution<long>(0, save_us / 4)(rng)));
        } else {
            std::this_thread::sleep_for(std::chrono::microseconds(
                std::uniform_int_distribution<long>(0, save_us * 2)(rng)));
        }
        ASSERT_EQ(::kill(child, SIGKILL), 0);
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL)
            << "the child ended before it was killed (status " << status << ")";
        drain(pipe_fds[0], saved, failed);
        ::close(pipe_fds[0]);

        // The scene is exactly one of the complete texts.
        const std::string now = read_file(target);
        const bool complete = std::find(texts.begin(), texts.end(), now) != texts.end();
        ASSERT_TRUE(complete) << "kill " << kill << " left a scene of " << now.size()
                              << " bytes that is no complete document";
        // Beside it at most one temporary file: the one this child was writing, or (killed
        // before its first save began) the one an earlier child left, which a save removes.
        const auto names = entries(dir);
        ASSERT_LE(names.size(), 2u) << "kill " << kill << " left " << names.back() << " and more";
        const bool left_tmp = names.size() == 2 && names[1] == fs::path(tmp).filename();
        if (names.size() == 2 && !left_tmp) {
            EXPECT_EQ(names[1], stray) << "kill " << kill;
        }
        mid_write += left_tmp;
        stray = names.size() == 2 ? names[1] : "";
    }
    EXPECT_EQ(failed, 0) << "a save failed outright";
    EXPECT_GT(mid_write, 0) << "no kill landed while the temporary file was being written";

    // The real load path agrees, and the next save clears the dead child's temporary file.
    auto loaded = load_scene(target);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(same_document(*loaded, docs[0]) || same_document(*loaded, docs[1]) ||
                same_document(*loaded, docs[2]));
    ASSERT_TRUE(save_scene(docs[0], target).ok());
    EXPECT_EQ(entries(dir), std::vector<std::string>{"scene.json"});

    std::cout << "[ figures  ] " << kills << " kills (" << mid_write
              << " while the temporary file was being written), " << saved
              << " saves completed in between, the scene intact after every kill\n";
}
