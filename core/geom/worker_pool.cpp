#include "core/geom/worker_pool.hpp"

#include <algorithm>

namespace isoparm::geom {

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

void WorkerPool::work(Job& job) {
    for (;;) {
        // Relaxed is enough: the tasks' inputs were published under m_ before the job was
        // visible, and their results reach the caller through m_ (active_) or its own thread.
        const int k = job.next.fetch_add(1, std::memory_order_relaxed);
        if (k >= job.tasks) return;
        try {
            job.call(job.fn, k);
        } catch (...) {
            const std::lock_guard lock(m_);
            if (!job.error) job.error = std::current_exception();
            job.next.store(job.tasks, std::memory_order_relaxed); // hand out no more
        }
    }
}

void WorkerPool::helper_loop() {
    unsigned long seen = 0;
    std::unique_lock lock(m_);
    for (;;) {
        wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
        if (stop_) return;
        seen = generation_;
        Job* job = job_;
        // A helper that wakes after its job ended finds job_ null (or a later job's limit).
        if (!job || job->joined >= job->max_helpers) continue;
        ++job->joined;
        ++active_;
        lock.unlock();
        work(*job);
        lock.lock();
        if (--active_ == 0) idle_.notify_all();
    }
}

void WorkerPool::run_impl(int tasks, int threads, void (*call)(void*, int), void* fn) {
    if (tasks <= 0) return;
    threads = std::min(threads, tasks);
    std::unique_lock busy(busy_, std::try_to_lock);
    if (threads <= 1 || !busy.owns_lock()) {
        for (int k = 0; k < tasks; ++k) call(fn, k);
        return;
    }
    Job job;
    job.call = call;
    job.fn = fn;
    job.tasks = tasks;
    job.max_helpers = threads - 1;
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
    }
    wake_.notify_all();
    work(job);
    std::exception_ptr error;
    {
        std::unique_lock lock(m_);
        // Every task has been handed out; the helpers still inside the job finish theirs.
        idle_.wait(lock, [&] { return active_ == 0; });
        job_ = nullptr;
        error = job.error;
    }
    if (error) std::rethrow_exception(error);
}

} // namespace isoparm::geom
