// Inputs that cannot block or abort: a FIFO, a directory, /proc/self/mem,
// a device, inputs above the cap; and the on-disk stamp that tells a file changed (item 5).
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "core/json/input_file.hpp"
#include "core/scene/scene_io.hpp"
#include "tests/support/temp_dir.hpp"

namespace fs = std::filesystem;
using isoparm::geom::ErrorCode;
using isoparm::json_io::changed_on_disk;
using isoparm::json_io::read_descriptor;
using isoparm::json_io::read_input_file;
using isoparm::json_io::stamp_of;
using isoparm::scene::load_scene;

namespace {

class InputFile : public ::testing::Test {
protected:
    std::string path(const std::string& name) const { return tmp_.path(name); }
    isoparm::test::TempDir tmp_{"isoparm-input"};
    const fs::path& dir_ = tmp_.dir();
};

// Runs `body` in a child with an alarm: a call that blocks (the old open of a FIFO) fails the
// test with SIGALRM instead of hanging the suite. The child's exit status is body's result.
template <class Body> void expect_in_child_without_blocking(Body body) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::alarm(20);
        ::_exit(body() ? 0 : 1);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status))
        << "the child was killed by signal " << WTERMSIG(status) << " (SIGALRM = it blocked)";
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST_F(InputFile, AFifoIsRefusedWithoutWaitingForAWriter) {
    ASSERT_EQ(::mkfifo(path("scene.json").c_str(), 0600), 0);
    const std::string fifo = path("scene.json");
    expect_in_child_without_blocking([&] {
        const auto r = read_input_file(fifo);
        return !r && r.error().message.find("a FIFO") != std::string::npos &&
               r.error().message.find(fifo) != std::string::npos;
    });
    expect_in_child_without_blocking([&] {
        const auto doc = load_scene(fifo); // render and the window load through here
        return !doc && doc.error().code == ErrorCode::internal;
    });
}

TEST_F(InputFile, ADirectoryADeviceAndProcSelfMemAreCleanErrors) {
    const auto d = read_input_file(dir_.string());
    ASSERT_FALSE(d);
    EXPECT_NE(d.error().message.find("a directory"), std::string::npos);
    const auto z = read_input_file("/dev/zero"); // would grow without end if read
    ASSERT_FALSE(z);
    EXPECT_NE(z.error().message.find("character device"), std::string::npos);
    // A "regular" file of size 0 whose read fails (EIO): an error, not an abort.
    const auto mem = read_input_file("/proc/self/mem");
    ASSERT_FALSE(mem);
    EXPECT_NE(mem.error().message.find("/proc/self/mem"), std::string::npos);
    const auto missing = read_input_file(path("missing.json"));
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().message.find("No such file"), std::string::npos);
}

TEST_F(InputFile, InputsAboveTheCapAreLimitErrors) {
    std::ofstream(path("big.json")) << std::string(1000, ' ');
    const auto file = read_input_file(path("big.json"), 999);
    ASSERT_FALSE(file);
    EXPECT_EQ(file.error().code, ErrorCode::limit);
    EXPECT_TRUE(read_input_file(path("big.json"), 1000));

    // Standard input has no size to check first: the reader stops at the cap.
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    // The reader stops early and closes its end: the writer then gets EPIPE, not a signal.
    const auto old_handler = ::signal(SIGPIPE, SIG_IGN);
    std::thread writer([w = fds[1]] {
        const std::string chunk(4096, 'x');
        for (int k = 0; k < 64; ++k)
            if (::write(w, chunk.data(), chunk.size()) < 0) break;
        ::close(w);
    });
    const auto piped = read_descriptor(fds[0], "standard input", 10000);
    ::close(fds[0]);
    writer.join();
    ::signal(SIGPIPE, old_handler);
    ASSERT_FALSE(piped);
    EXPECT_EQ(piped.error().code, ErrorCode::limit);
    EXPECT_NE(piped.error().message.find("standard input"), std::string::npos);
}

TEST_F(InputFile, AStampTellsAFileChangedOnDisk) {
    const std::string p = path("scene.json");
    EXPECT_FALSE(changed_on_disk(p, stamp_of(p))); // neither exists
    std::ofstream(p) << "one";
    const auto first = stamp_of(p);
    ASSERT_TRUE(first);
    EXPECT_FALSE(changed_on_disk(p, first));
    // Another program saves atomically: a new file under the same name.
    std::ofstream(path("other.json")) << "two";
    fs::rename(path("other.json"), p);
    EXPECT_TRUE(changed_on_disk(p, first));
    const auto second = stamp_of(p);
    // Or writes it in place (a different size: two writes within one clock tick of the file
    // system's timestamps cannot be told apart by stat).
    std::ofstream(p, std::ios::trunc) << "three";
    EXPECT_TRUE(changed_on_disk(p, second));
    fs::remove(p);
    EXPECT_TRUE(changed_on_disk(p, second));
}

} // namespace
