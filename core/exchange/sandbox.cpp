#include "core/exchange/sandbox.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/sanitizer_build.hpp"

namespace isoparm::exchange {

namespace {

#ifndef ISOPARM_ASAN // AddressSanitizer's shadow memory and RLIMIT_AS do not mix
// The address space this process has mapped now (/proc/self/statm: size in pages), or 0.
std::size_t mapped_bytes() {
    std::FILE* f = std::fopen("/proc/self/statm", "r");
    if (!f) return 0;
    unsigned long pages = 0;
    const int got = std::fscanf(f, "%lu", &pages);
    std::fclose(f);
    return got == 1 ? pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)) : 0;
}
#endif

void set_limit(int resource, rlim_t soft, rlim_t hard) {
    struct rlimit now {};
    if (::getrlimit(resource, &now) != 0) return;
    // Never above what this process may have: a user's ulimit stays in force.
    if (now.rlim_max != RLIM_INFINITY) {
        soft = std::min(soft, now.rlim_max);
        hard = std::min(hard, now.rlim_max);
    }
    if (now.rlim_cur != RLIM_INFINITY) soft = std::min(soft, now.rlim_cur);
    struct rlimit next {
        soft, std::max(soft, hard)
    };
    (void)::setrlimit(resource, &next);
}

// The child's side, from fork to _exit: nothing here returns.
[[noreturn]] void child(int fd, const std::function<void(int)>& body, const SandboxLimits& limits) {
    // Die with the parent (a child reading forever for nobody would be a leak of its own).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    // If memory runs short, the kernel's out-of-memory killer takes the child, not the program.
    if (std::FILE* f = std::fopen("/proc/self/oom_score_adj", "w")) {
        std::fputs("1000", f);
        std::fclose(f);
    }
    set_limit(RLIMIT_CORE, 0, 0); // a crash leaves no core file behind
#ifdef ISOPARM_ASAN
    // A crash in the child is the outcome the parent measures (OCCT on a hostile file), not a
    // bug of this program: AddressSanitizer's SEGV handler would turn it into its report and an
    // abort, so the child dies of the signal itself, as in a normal build.
    for (const int deadly : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(deadly, SIG_DFL);
#endif
    const auto cpu = static_cast<rlim_t>(std::ceil(std::max(1.0, limits.cpu_seconds)));
    set_limit(RLIMIT_CPU, cpu, cpu + 5);
#ifndef ISOPARM_ASAN
    if (limits.memory_bytes > 0)
        if (const std::size_t now = mapped_bytes(); now > 0)
            set_limit(RLIMIT_AS, now + limits.memory_bytes, now + limits.memory_bytes);
#endif
    const int null = ::open("/dev/null", O_RDWR | O_CLOEXEC);
    if (null >= 0) {
        ::dup2(null, STDIN_FILENO);
        ::dup2(null, STDOUT_FILENO);
#ifndef ISOPARM_ASAN
        ::dup2(null, STDERR_FILENO); // under the sanitizers their reports stay visible
#endif
    }
    int status = 0;
    try {
        body(fd);
    } catch (const std::bad_alloc&) {
        status = 4;
    } catch (...) {
        status = 3;
    }
    ::_exit(status);
}

} // namespace

double wall_seconds_for(double cpu_seconds) {
    return 3 * cpu_seconds + 5;
}

SandboxLimits sandbox_limits_for(std::size_t input_bytes) {
    const double megabytes = static_cast<double>(input_bytes) / 1e6;
    SandboxLimits l;
    l.cpu_seconds = 10 + 2 * megabytes;
    l.wall_seconds = wall_seconds_for(l.cpu_seconds);
    std::size_t memory = (std::size_t{2} << 30) + 24 * input_bytes;
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0)
        memory = std::min(memory, static_cast<std::size_t>(pages) * page / 4 * 3);
    l.memory_bytes = memory;
    return l;
}

bool write_to_parent(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

std::string describe_signal(int signal) {
    const char* abbrev = ::sigabbrev_np(signal);
    const char* text = ::sigdescr_np(signal);
    std::string out = "signal " + std::to_string(signal);
    if (abbrev) out += std::string(" (SIG") + abbrev + (text ? std::string(": ") + text : "") + ")";
    return out;
}

SandboxRun run_sandboxed(const std::function<void(int fd)>& body, const SandboxLimits& limits) {
    SandboxRun run;
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) {
        run.why_not_started = std::string("no pipe to a child process: ") + std::strerror(errno);
        return run;
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
        run.why_not_started = std::string("no child process: ") + std::strerror(errno);
        ::close(fds[0]);
        ::close(fds[1]);
        return run;
    }
    if (pid == 0) {
        ::close(fds[0]);
        child(fds[1], body, limits);
    }
    ::close(fds[1]);

    using clock = std::chrono::steady_clock;
    const auto deadline =
        clock::now() + std::chrono::milliseconds(static_cast<long long>(limits.wall_seconds * 1e3));
    bool killed = false, too_much = false;
    char buffer[1 << 16];
    while (true) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now());
        if (left.count() <= 0) {
            ::kill(pid, SIGKILL);
            killed = true;
            break;
        }
        struct pollfd p {
            fds[0], POLLIN, 0
        };
        const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR) break;
        if (ready <= 0) continue;
        const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break; // end of the child's output (it ended, or closed it on its way out)
        run.output.append(buffer, static_cast<std::size_t>(n));
        if (limits.output_bytes > 0 && run.output.size() > limits.output_bytes) {
            ::kill(pid, SIGKILL);
            killed = too_much = true;
            break;
        }
    }
    ::close(fds[0]);
    int status = 0;
    while (true) {
        const pid_t got = ::waitpid(pid, &status, killed ? 0 : WNOHANG);
        if (got == pid) break;
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) break;
        // The pipe closed but the child has not ended yet: give it until the deadline.
        if (clock::now() >= deadline) {
            ::kill(pid, SIGKILL);
            killed = true;
        } else {
            ::usleep(1000);
        }
    }
    if (too_much) {
        run.ending = SandboxRun::Ending::too_much;
    } else if (killed) {
        run.ending = SandboxRun::Ending::timed_out;
    } else if (WIFSIGNALED(status)) {
        run.ending = SandboxRun::Ending::signaled;
        run.signal = WTERMSIG(status);
    } else {
        run.ending = SandboxRun::Ending::exited;
        run.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 0;
    }
    return run;
}

} // namespace isoparm::exchange
