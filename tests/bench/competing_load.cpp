#include "tests/bench/competing_load.hpp"

#include <algorithm>
#include <chrono>
#include <thread>

#if defined(__linux__)
#include <csignal>
#include <sched.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace isoparm::bench {

#if defined(__linux__)
namespace {
// The child: spins on arithmetic (no memory traffic, no system calls) until killed. It dies
// with the benchmark too (PR_SET_PDEATHSIG), so a crash leaves no spinner behind.
[[noreturn]] void spin(pid_t parent) {
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent) _exit(0); // the parent died before the line above
    volatile double x = 1.0;
    for (;;) x = x * 0.999999 + 1e-6;
}
} // namespace

CompetingLoad::CompetingLoad(int processes) {
    const pid_t parent = getpid();
    for (int k = 0; k < processes; ++k) {
        const pid_t pid = fork();
        if (pid == 0) spin(parent);
        if (pid > 0) pids_.push_back(pid);
    }
    // Let them reach the run queues before anything is timed.
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
}

CompetingLoad::~CompetingLoad() {
    for (int pid : pids_) kill(pid, SIGKILL);
    for (int pid : pids_) waitpid(pid, nullptr, 0);
}

int available_cores() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
    return std::max(1u, std::thread::hardware_concurrency());
}
#else
CompetingLoad::CompetingLoad(int) {}
CompetingLoad::~CompetingLoad() = default;
int available_cores() {
    return std::max(1u, std::thread::hardware_concurrency());
}
#endif

} // namespace isoparm::bench
