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

int WorkerPool::work(Job& job) {
    for (int ran = 0;; ++ran) {
        // Relaxed is enough: the tasks' inputs were published under m_ before the job was
        // visible, and their results reach the caller through m_ (active_) or its own thread.
        const int h = job.next.fetch_add(1, std::memory_order_relaxed);
        if (h >= job.tasks) return ran;
        try {
            job.call(job.fn, handout_task(h, job.tasks, job.threads));
        } catch (...) {
            const std::lock_guard lock(m_);
            if (!job.error) job.error = std::current_exception();
            job.next.store(job.tasks, std::memory_order_relaxed); // hand out no more
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
        Job* job = job_;
        // A helper that comes after its job ended finds job_ null (or a later job's limit).
        if (!job || job->joined >= job->max_helpers) continue;
        ++job->joined;
        ++active_;
        lock.unlock();
        const double cpu0 = thread_cpu_seconds();
        work(*job);
        const double cpu1 = thread_cpu_seconds();
        lock.lock();
        job->helper_cpu += cpu0 >= 0 && cpu1 >= 0 ? cpu1 - cpu0 : 1e300; // no clock: no verdict
        if (--active_ == 0) idle_.notify_all();
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
    job.call = call;
    job.fn = fn;
    job.tasks = tasks;
    job.threads = threads;
    job.max_helpers = threads - 1;
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
        job_ = &job;
        ++generation_;
        sleeping = sleepers_ > 0;
    }
    // Spinning helpers see generation_ change; only blocked ones need the (system) call.
    if (sleeping) wake_.notify_all();
    work(job);
    const double cpu1 = thread_cpu_seconds();
    // Every task has been handed out; the helpers still inside the job finish theirs (for
    // less than a task: spin first). The lock below then also orders their writes before ours.
    spin_until([&] { return active_.load(std::memory_order_relaxed) == 0; });
    std::exception_ptr error;
    double helper_cpu = 0;
    {
        std::unique_lock lock(m_);
        idle_.wait(lock, [&] { return active_ == 0; });
        job_ = nullptr;
        error = job.error;
        helper_cpu = job.helper_cpu;
    }
    // The guard: this call's wall time against its threads' CPU time in the tasks.
    const Clock::time_point done = Clock::now();
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
