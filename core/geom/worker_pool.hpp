// A persistent pool of helper threads for data-parallel loops (grid tessellation): started
// lazily on the first call that asks for more than one thread, kept for the process, joined
// on destruction, so a drag that re-tessellates every frame never pays for thread start-up.
#pragma once

#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace isoparm::geom {

class WorkerPool {
public:
    WorkerPool() = default;
    ~WorkerPool(); // stops and joins the helpers
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // The process's pool.
    static WorkerPool& shared();

    // Calls fn(k) for k = 0 .. tasks - 1 on the calling thread and at most threads - 1 helpers,
    // and returns when every call has returned (their writes are then visible to the caller).
    // Tasks are handed out one at a time, in increasing k. When the pool is already running
    // another caller's loop (another thread, or fn itself calling run), the tasks run on the
    // calling thread alone: nested and concurrent calls never wait for each other. The first
    // exception a task throws is rethrown here after the others finished.
    template <class F> void run(int tasks, int threads, F&& fn) {
        using Fn = std::remove_reference_t<F>;
        run_impl(
            tasks, threads, [](void* f, int k) { (*static_cast<Fn*>(f))(k); },
            const_cast<void*>(static_cast<const void*>(&fn)));
    }

    // Helper threads started so far.
    int helpers() const;

private:
    struct Job {
        void (*call)(void*, int) = nullptr;
        void* fn = nullptr;
        int tasks = 0;
        int max_helpers = 0;
        int joined = 0;
        std::atomic<int> next{0};
        std::exception_ptr error; // guarded by m_
    };
    void run_impl(int tasks, int threads, void (*call)(void*, int), void* fn);
    void work(Job& job);
    void helper_loop();

    std::mutex busy_; // held by the caller whose loop the helpers serve
    mutable std::mutex m_;
    std::condition_variable wake_, idle_;
    std::vector<std::thread> threads_; // guarded by m_
    Job* job_ = nullptr;               // guarded by m_
    unsigned long generation_ = 0;     // guarded by m_
    int active_ = 0;                   // helpers inside job_, guarded by m_
    bool stop_ = false;                // guarded by m_
};

} // namespace isoparm::geom
