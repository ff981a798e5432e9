// The sandbox that third-party readers run in (core/exchange/sandbox.hpp): what a child writes
// comes back; a crash, a CPU limit, a timeout and an address-space limit end the child, never
// this process, and each is told apart; nothing the child prints reaches this process's
// standard output; no child is left behind.
#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "core/exchange/sandbox.hpp"

using namespace isoparm::exchange;

namespace {

SandboxLimits quick() {
    SandboxLimits l;
    l.cpu_seconds = 1;
    l.wall_seconds = 20;
    l.memory_bytes = std::size_t{256} << 20;
    return l;
}

// A real crash, the way a third-party reader crashes: a store through a null pointer. The
// undefined-behaviour sanitizer would stop at the store itself, before the signal this test
// is about.
__attribute__((no_sanitize("undefined"))) void store_through_null() {
    volatile int* null = nullptr;
    *null = 1;
}

void expect_no_child_left() {
    int status = 0;
    EXPECT_EQ(::waitpid(-1, &status, WNOHANG), -1);
}

TEST(Sandbox, WhatTheChildWritesComesBack) {
    const SandboxRun run = run_sandboxed(
        [](int fd) {
            std::string big(3 << 20, 'x'); // more than a pipe holds at once
            write_to_parent(fd, "hello ");
            write_to_parent(fd, big);
        },
        quick());
    EXPECT_EQ(run.ending, SandboxRun::Ending::exited);
    EXPECT_EQ(run.exit_status, 0);
    ASSERT_EQ(run.output.size(), 6u + (3u << 20));
    EXPECT_EQ(run.output.substr(0, 6), "hello ");
    expect_no_child_left();
}

TEST(Sandbox, ACrashIsASignalNotTheEndOfThisProcess) {
    const SandboxRun run = run_sandboxed(
        [](int fd) {
            write_to_parent(fd, "before");
            store_through_null();
        },
        quick());
    EXPECT_EQ(run.ending, SandboxRun::Ending::signaled);
    EXPECT_EQ(run.signal, SIGSEGV);
    EXPECT_EQ(run.output, "before");
    EXPECT_EQ(describe_signal(SIGSEGV), "signal 11 (SIGSEGV: Segmentation fault)");
    expect_no_child_left();
}

TEST(Sandbox, AnEndlessLoopMeetsTheCpuLimit) {
    const SandboxRun run = run_sandboxed(
        [](int) {
            volatile unsigned long spin = 0;
            while (true) spin = spin + 1;
        },
        quick());
    EXPECT_EQ(run.ending, SandboxRun::Ending::signaled);
    EXPECT_TRUE(run.signal == SIGXCPU || run.signal == SIGKILL) << run.signal;
    expect_no_child_left();
}

TEST(Sandbox, AChildThatWaitsForeverMeetsTheWallClock) {
    SandboxLimits l = quick();
    l.wall_seconds = 0.5;
    const SandboxRun run = run_sandboxed([](int) { ::pause(); }, l);
    EXPECT_EQ(run.ending, SandboxRun::Ending::timed_out);
    expect_no_child_left();
}

#if !defined(__SANITIZE_ADDRESS__)
TEST(Sandbox, MemoryBeyondTheLimitIsRefusedToTheChildOnly) {
    const SandboxRun run = run_sandboxed(
        [](int fd) {
            std::vector<char*> blocks;
            for (int k = 0; k < 64; ++k) { // 64 x 64 MiB = 4 GiB, far over the 256 MiB limit
                char* p = static_cast<char*>(std::malloc(std::size_t{64} << 20));
                if (!p) {
                    write_to_parent(fd, "refused");
                    return;
                }
                std::memset(p, 1, std::size_t{64} << 20);
                blocks.push_back(p);
            }
            write_to_parent(fd, "not refused");
        },
        quick());
    EXPECT_EQ(run.ending, SandboxRun::Ending::exited);
    EXPECT_EQ(run.output, "refused");
    expect_no_child_left();
}
#endif

TEST(Sandbox, OutOfMemoryThrownInTheChildIsItsOwnStatus) {
    const SandboxRun run = run_sandboxed([](int) { throw std::bad_alloc(); }, quick());
    EXPECT_EQ(run.ending, SandboxRun::Ending::exited);
    EXPECT_EQ(run.exit_status, 4);
}

TEST(Sandbox, TheChildsStandardOutputIsNotThisProcesss) {
    // A pipe stands in for this process's standard output while the child runs.
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const int saved = ::dup(STDOUT_FILENO);
    ::dup2(fds[1], STDOUT_FILENO);
    const SandboxRun run = run_sandboxed(
        [](int) {
            const char text[] = "from the child\n";
            (void)!::write(STDOUT_FILENO, text, sizeof text - 1);
        },
        quick());
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    ::close(fds[1]);
    char buffer[64];
    EXPECT_EQ(::read(fds[0], buffer, sizeof buffer), 0);
    ::close(fds[0]);
    EXPECT_EQ(run.ending, SandboxRun::Ending::exited);
}

TEST(Sandbox, SharedMemoryTellsHowFarTheChildGot) {
    struct Progress {
        std::atomic<int> step{0};
    };
    SharedWithChild<Progress> progress;
    const SandboxRun run = run_sandboxed(
        [&](int) {
            progress->step = 7;
            std::abort();
        },
        quick());
    EXPECT_EQ(run.ending, SandboxRun::Ending::signaled);
    EXPECT_EQ(run.signal, SIGABRT);
    EXPECT_EQ(progress->step.load(), 7);
    progress.reset();
    EXPECT_EQ(progress->step.load(), 0);
}

TEST(Sandbox, AChildThatWritesTooMuchIsStopped) {
    SandboxLimits l = quick();
    l.output_bytes = 1 << 20;
    const SandboxRun run = run_sandboxed(
        [](int fd) {
            const std::string block(1 << 16, 'x');
            while (write_to_parent(fd, block)) {
            }
        },
        l);
    EXPECT_EQ(run.ending, SandboxRun::Ending::too_much);
    EXPECT_LE(run.output.size(), (1u << 20) + (1u << 16));
    expect_no_child_left();
}

TEST(Sandbox, LimitsGrowWithTheInput) {
    const SandboxLimits small = sandbox_limits_for(1000), big = sandbox_limits_for(50'000'000);
    EXPECT_GE(small.cpu_seconds, 10);
    EXPECT_GT(big.cpu_seconds, small.cpu_seconds);
    EXPECT_GT(big.wall_seconds, big.cpu_seconds);
    EXPECT_GE(big.memory_bytes, small.memory_bytes);
}

} // namespace
