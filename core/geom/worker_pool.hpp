// A persistent pool of helper threads for data-parallel loops (grid tessellation): started
// lazily on the first call that asks for more than one thread, kept for the process, joined
// on destruction, so a drag that re-tessellates every frame never pays for thread start-up.
//
// Helpers and the caller wait by spinning for a short while before they block: on a virtual
// machine, waking a blocked thread (a futex wake plus the halted virtual CPU's exit) was
// measured at 30-100 us, half a 256x256 grid of positions, while loops called back to back
// (benchmarks, batch tessellation) then find their helpers still spinning.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace isoparm::geom {

class WorkerPool {
public:
    // How long an idle helper (or a caller waiting for its helpers) spins before it blocks: a
    // few times the measured wake-up cost, so spinning costs at most that per idle period.
    static constexpr std::chrono::microseconds spin_time{250};

    WorkerPool() = default;
    ~WorkerPool(); // stops and joins the helpers
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    // The process's pool.
    static WorkerPool& shared();

    // Calls fn(k) for k = 0 .. tasks - 1 on the calling thread and at most threads - 1 helpers,
    // and returns when every call has returned (their writes are then visible to the caller).
    // Tasks are handed out one at a time, in the order of handout_task: threads that run at
    // the same time work on tasks far apart, not on neighbours (which typically write
    // neighbouring memory, sharing cache lines at their ends). Whoever is free claims the next
    // task, so the caller takes over the tasks of a helper that is late or descheduled; it
    // waits only for tasks a helper has claimed and not finished, and a helper that has not
    // claimed one by the time the caller ran out does nothing. When the pool is already running
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

    // The contention guard. Under competing load two threads can lose badly to one: waking a
    // helper puts it on a busy core or on the caller's own (whose time it then takes), and a
    // helper preempted in the middle of a task keeps the caller waiting for a time slice
    // (measured 2.8 ms instead of 0.1 ms for a 256 x 256 grid at a load of 15 on two cores).
    // So each call with helpers compares its wall time with the CPU time its threads spent in
    // the tasks (what one thread running them without interruption would take); where the
    // wall time was longer by more than an eighth (and 20 us), the next calls run on the caller
    // alone for solo_start, twice that after a second loss and so on up to solo_max, and then
    // try the helpers again. A call they win (wall time under 0.8 of the CPU time) halves the
    // span; one about even keeps it, and the calls after it on the caller too. Where threads
    // have no CPU clock the guard stays off.
    static constexpr std::chrono::milliseconds solo_start{50}, solo_max{1600};
    // Whether calls now run on the caller alone (the guard's last verdict is still on).
    bool solo() const;

    // The task of the h-th handout when `tasks` are shared by `threads`: the tasks are cut into
    // `threads` runs of q = ceil(tasks / threads) and handed out across them, 0, q, 2q, ..., 1,
    // q + 1, 2q + 1, ..., so that each thread works down a run of its own (and takes over the
    // others' where it is faster). A permutation of 0 .. tasks - 1; the identity for one thread.
    static int handout_task(int h, int tasks, int threads);

private:
    // The loop being run: published under m_, copied by each helper as it joins.
    struct Job {
        void (*call)(void*, int) = nullptr; // null: no loop to join
        void* fn = nullptr;
        int tasks = 0;
        int threads = 1; // handout_task's
        int max_helpers = 0;
        int joined = 0;
        std::uint32_t tag = 0; // the low bits of its generation, as in claim_
    };
    void run_impl(int tasks, int threads, void (*call)(void*, int), void* fn);
    // The next handout of the job, or -1 when none is left (or the job is over).
    int claim(const Job& job);
    // Claims and runs the job's tasks until none is left; helper: also counts its CPU time.
    void work(const Job& job, bool helper);
    void helper_loop();

    std::mutex busy_; // held by the caller whose loop the helpers serve
    mutable std::mutex m_;
    std::condition_variable wake_, idle_;
    std::vector<std::thread> threads_; // guarded by m_
    Job job_;                          // guarded by m_
    // Written under m_; also read without it by spinning helpers and a spinning caller (who
    // then take m_ before they act on what they saw).
    std::atomic<unsigned long> generation_{0};
    std::atomic<bool> stop_{false};
    int sleepers_ = 0; // helpers blocked on wake_, guarded by m_
    // The handouts: the job's tag (high 32 bits) and the next handout (low 32). A thread claims
    // a handout only while the tag is its job's, so a helper that joined but was descheduled
    // before it claimed anything cannot take a later job's tasks, and the caller never waits
    // for it: the caller waits for its tasks only (completed_), never for helpers as such.
    std::atomic<std::uint64_t> claim_{0};
    std::atomic<int> completed_{0};           // the job's tasks run (or skipped after a throw)
    std::atomic<bool> failed_{false};         // a task threw: the others are skipped
    std::atomic<long long> helper_cpu_ns_{0}; // the helpers' CPU time in the job's tasks
    std::exception_ptr error_;                // the first exception, guarded by m_
    // The contention guard (guarded by busy_; solo_until_ also read by solo()).
    std::atomic<std::chrono::steady_clock::rep> solo_until_{0};
    std::chrono::steady_clock::duration solo_span_{0};
};

} // namespace isoparm::geom
