// Third-party code that can crash, loop or exhaust memory on a malformed file runs in a child
// process with limits, the way browsers isolate their decoders: fork, setrlimit (address space,
// CPU time, no core file), a pipe back. The parent turns a signal or a timeout into an error
// message; the program and its unsaved work are never at stake. (OpenCASCADE's IGES and STEP
// readers run this way: core/exchange_occt/occt_reader.cpp.)
#pragma once

#include <cstddef>
#include <functional>
#include <new>
#include <string>
#include <sys/mman.h>
#include <type_traits>

namespace isoparm::exchange {

struct SandboxLimits {
    double cpu_seconds = 10;  // RLIMIT_CPU: SIGXCPU at this many seconds of CPU time
    double wall_seconds = 35; // the parent kills the child (SIGKILL) after this long
    // Address space the child may map beyond what it starts with (the parent's, shared
    // copy-on-write); 0 sets no limit. Not set under AddressSanitizer, whose shadow memory
    // needs terabytes of address space.
    std::size_t memory_bytes = std::size_t{2} << 30;
    // The most the child may write back; past it the parent stops it (kills it) and says so
    // (0: no limit).
    std::size_t output_bytes = 0;
};

// The limits for reading `input_bytes` of text: 10 s of CPU plus 2 s per MB (OpenCASCADE
// reads a STEP file at 5 to 20 MB/s), wall_seconds_for that, 2 GiB plus 24 bytes per byte of
// input (a 50 MB STEP file needs about 0.5 GB in OpenCASCADE), never more than three quarters
// of the machine's memory.
SandboxLimits sandbox_limits_for(std::size_t input_bytes);
// Three times the CPU time and 5 s more: a busy machine gives a child a fraction of a core.
double wall_seconds_for(double cpu_seconds);

struct SandboxRun {
    enum class Ending {
        exited,      // the child ended by itself (exit_status says how)
        signaled,    // a signal ended it (signal)
        timed_out,   // the wall-time limit ran out and the parent killed it
        too_much,    // it wrote more than output_bytes and the parent killed it
        not_started, // fork or pipe failed (why_not_started)
    };
    Ending ending = Ending::not_started;
    int exit_status = 0;
    int signal = 0;
    std::string why_not_started;
    std::string output; // every byte the child wrote to its pipe
};

// Runs body(fd) in a forked child, `fd` the write end of a pipe whose bytes the parent
// collects, then ends the child with _exit(0) (never exit(): the parent's atexit handlers and
// stdio buffers are not the child's). In the child, standard output goes to /dev/null (it is
// the parent's, and `isoparm import -o -` writes the scene there), and the child dies with
// the parent. An exception escaping body ends the child with status 3 (std::bad_alloc: 4).
// Blocks until the child has ended; safe to call from several threads.
SandboxRun run_sandboxed(const std::function<void(int fd)>& body, const SandboxLimits& limits);

// Writes all of `bytes` to `fd` (in the child: false when the parent is gone).
bool write_to_parent(int fd, std::string_view bytes);

// "signal 11 (SIGSEGV: Segmentation fault)".
std::string describe_signal(int signal);

// Memory shared by the parent and the children it forks (one anonymous MAP_SHARED mapping):
// how a child tells how far it got, read by the parent after the child died. T holds plain
// values and atomics.
template <class T> class SharedWithChild {
    static_assert(std::is_trivially_destructible_v<T>);

public:
    SharedWithChild() {
        void* p =
            ::mmap(nullptr, sizeof(T), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
        if (p == MAP_FAILED) throw std::bad_alloc();
        value_ = new (p) T{};
    }
    ~SharedWithChild() { ::munmap(value_, sizeof(T)); }
    SharedWithChild(const SharedWithChild&) = delete;
    SharedWithChild& operator=(const SharedWithChild&) = delete;
    T& operator*() { return *value_; }
    T* operator->() { return value_; }
    // A fresh value for the next child.
    void reset() { value_ = new (value_) T{}; }

private:
    T* value_ = nullptr;
};

} // namespace isoparm::exchange
