#include "core/geom/worker_pool.hpp"

#include <algorithm>
#include <ctime>

namespace isoparm::geom {

namespace {

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#else
    std::this_thread::yield();
#endif
}

// Spins until done() or WorkerPool::spin_time has passed; returns done()'s last value. The
// clock is read every 64 pauses (a pause is tens of cycles: far finer than the budget).
template <class Done> bool spin_until(Done done) {
    const auto end = std::chrono::steady_clock::now() + WorkerPool::spin_time;
    for (;;) {
        for (int k = 0; k < 64; ++k) {
            if (done()) return true;
            cpu_relax();
        }
        if (std::chrono::steady_clock::now() >= end) return done();
    }
}

// The calling thread's CPU time in seconds, or a negative value where there is no such clock.
double thread_cpu_seconds() {
    timespec t{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) != 0) return -1;
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

} // namespace

WorkerPool& WorkerPool::shared() {
    static WorkerPool pool;
    return pool;
}

WorkerPool::~WorkerPool() {
    {
        const std::lock_guard lock(m_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
}

int WorkerPool::helpers() const {
    const std::lock_guard lock(m_);
    return static_cast<int>(threads_.size());
}

int WorkerPool::handout_task(int h, int tasks, int threads) {
    const int q = (tasks + threads - 1) / threads;
    const int runs = (tasks + q - 1) / q;    // runs that are not empty
    const int last = tasks - (runs - 1) * q; // tasks in the last run, 1 .. q
    if (h < last * runs) return h % runs * q + h / runs;
    h -= last * runs; // the last run is used up: the others' remaining tasks
    return h % (runs - 1) * q + last + h / (runs - 1);
}

bool WorkerPool::solo() const {
    return std::chrono::steady_clock::now().time_since_epoch().count() <
           solo_until_.load(std::memory_order_relaxed);
}

int WorkerPool::claim(const Job& job) {
    // Relaxed is enough: the tasks' inputs were published under m_ before the job was visible,
    // and their results reach the caller through completed_ (release / acquire) or its own
    // thread.
    const std::uint64_t tag = static_cast<std::uint64_t>(job.tag) << 32;
    std::uint64_t c = claim_.load(std::memory_order_relaxed);
    do {
        if ((c & ~std::uint64_t{0xffffffff}) != tag ||
            static_cast<int>(c & 0xffffffff) >= job.tasks)
            return -1;
    } while (!claim_.compare_exchange_weak(c, c + 1, std::memory_order_relaxed));
    return static_cast<int>(c & 0xffffffff);
}

void WorkerPool::work(const Job& job, bool helper) {
    // A helper's CPU time is read once per job (the clock is a system call): its last task is
    // counted done only after that, so the caller, who waits for the count, reads all of it.
    const double cpu0 = helper ? thread_cpu_seconds() : 0;
    const auto count_done = [&] {
        if (completed_.fetch_add(1, std::memory_order_acq_rel) + 1 == job.tasks && helper) {
            const std::lock_guard lock(m_); // the caller may be blocked waiting for this one
            idle_.notify_all();
        }
        // (Past the last one the job may be over: only the pool's own members are touched.)
    };
    for (bool holding = false;;) {
        const int h = claim(job);
        if (h < 0) {
            if (!holding) return;
            if (helper) {
                const double cpu1 = thread_cpu_seconds();
                // No clock: no verdict (more CPU than any wall time).
                const double ns = cpu0 >= 0 && cpu1 >= 0 ? 1e9 * (cpu1 - cpu0) : 1e15;
                helper_cpu_ns_.fetch_add(static_cast<long long>(ns), std::memory_order_relaxed);
            }
            return count_done();
        }
        if (holding) count_done();
        holding = true;
        if (failed_.load(std::memory_order_relaxed)) continue; // a task threw: skip the rest
        try {
            job.call(job.fn, handout_task(h, job.tasks, job.threads));
        } catch (...) {
            const std::lock_guard lock(m_);
            if (!error_) error_ = std::current_exception();
            failed_.store(true, std::memory_order_relaxed);
        }
    }
}

void WorkerPool::helper_loop() {
    unsigned long seen = 0;
    for (;;) {
        const auto posted = [&] {
            return stop_.load(std::memory_order_relaxed) ||
                   generation_.load(std::memory_order_relaxed) != seen;
        };
        std::unique_lock lock(m_, std::defer_lock);
        if (spin_until(posted)) {
            lock.lock();
        } else {
            // run_impl changes generation_ and reads sleepers_ under m_: no wake-up is lost.
            lock.lock();
            ++sleepers_;
            wake_.wait(lock, posted);
            --sleepers_;
        }
        if (stop_) return;
        seen = generation_;
        // A helper that comes after its job ended finds no job (or a later job's limit).
        if (!job_.call || job_.joined >= job_.max_helpers) continue;
        ++job_.joined;
        const Job job = job_;
        lock.unlock();
        work(job, true);
    }
}

void WorkerPool::run_impl(int tasks, int threads, void (*call)(void*, int), void* fn) {
    if (tasks <= 0) return;
    threads = std::min(threads, tasks);
    std::unique_lock busy(busy_, std::try_to_lock);
    if (threads <= 1 || !busy.owns_lock() || solo()) {
        for (int k = 0; k < tasks; ++k) call(fn, k);
        return;
    }
    // From here the guard's clocks run: the wake-up below is where a woken helper can take the
    // caller's core.
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    const double cpu0 = thread_cpu_seconds();
    Job job;
    bool sleeping = false;
    {
        const std::lock_guard lock(m_);
        // Started lazily, never more than 63 (and a thread the system refuses is skipped).
        const int want = std::min(threads - 1, 63);
        while (static_cast<int>(threads_.size()) < want) {
            try {
                threads_.emplace_back([this] { helper_loop(); });
            } catch (const std::system_error&) {
                break;
            }
        }
        const unsigned long generation = ++generation_;
        job = Job{call, fn, tasks, threads, threads - 1, 0, static_cast<std::uint32_t>(generation)};
        job_ = job;
        completed_.store(0, std::memory_order_relaxed);
        failed_.store(false, std::memory_order_relaxed);
        helper_cpu_ns_.store(0, std::memory_order_relaxed);
        error_ = nullptr;
        claim_.store(static_cast<std::uint64_t>(job.tag) << 32, std::memory_order_relaxed);
        sleeping = sleepers_ > 0;
    }
    // Spinning helpers see generation_ change; only blocked ones need the (system) call.
    if (sleeping) wake_.notify_all();
    work(job, false);
    const double cpu1 = thread_cpu_seconds();
    // Every task has been claimed; tasks a helper still runs are waited for (spinning first:
    // less than a task's time when the helper is running).
    const auto all_done = [&] { return completed_.load(std::memory_order_acquire) == tasks; };
    std::exception_ptr error;
    {
        std::unique_lock lock(m_, std::defer_lock);
        if (!spin_until(all_done)) {
            lock.lock();
            idle_.wait(lock, all_done);
        } else {
            lock.lock();
        }
        job_ = Job{}; // helpers that wake from now on find nothing to join
        error = error_;
        error_ = nullptr;
    }
    // The guard: this call's wall time against its threads' CPU time in the tasks.
    const Clock::time_point done = Clock::now();
    const double helper_cpu = 1e-9 * static_cast<double>(helper_cpu_ns_.load());
    if (cpu0 >= 0 && cpu1 >= 0) {
        const double wall = std::chrono::duration<double>(done - start).count();
        const double cpu = cpu1 - cpu0 + helper_cpu;
        if (wall > cpu * 1.125 + 20e-6) { // lost
            solo_span_ = std::clamp<Clock::duration>(2 * solo_span_, solo_start, solo_max);
            solo_until_.store((done + solo_span_).time_since_epoch().count(),
                              std::memory_order_relaxed);
        } else if (wall < cpu * 0.8) { // won: the next loss is sent away for less long
            solo_span_ /= 2;
        } else if (solo_span_.count() > 0) { // about even after a loss: no gain, caller alone
            solo_until_.store((done + solo_span_).time_since_epoch().count(),
                              std::memory_order_relaxed);
        }
    }
    if (error) std::rethrow_exception(error);
}

} // namespace isoparm::geom
