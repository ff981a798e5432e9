// The persistent pool: every task runs exactly once, the helpers are started once and reused,
// nested and concurrent calls run on their caller, an exception reaches the caller, and the
// handout order keeps threads on runs of their own; a helper that keeps the caller waiting
// sends the next calls to the caller alone for a while.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "core/geom/worker_pool.hpp"

using isoparm::geom::WorkerPool;

TEST(WorkerPool, EveryTaskRunsOnceAndHelpersAreReused) {
    WorkerPool pool;
    EXPECT_EQ(pool.helpers(), 0); // lazily: nothing started before the first parallel call
    for (int round = 0; round < 200; ++round) {
        std::vector<int> hits(97, 0); // each task writes its own element: no race
        pool.run(97, 3, [&](int k) { hits[k] += 1; });
        for (int h : hits) ASSERT_EQ(h, 1);
    }
    EXPECT_EQ(pool.helpers(), 2);
    pool.run(5, 2, [](int) {});
    EXPECT_EQ(pool.helpers(), 2); // never more than asked for, never restarted
}

// Jobs back to back, of every size from 1 to 17 tasks, some slow: a helper that is still
// looking for work of one job must never take (or count) a task of the next.
TEST(WorkerPool, BackToBackJobsNeverShareTasks) {
    WorkerPool pool;
    for (int round = 0; round < 2000; ++round) {
        const int tasks = 1 + round % 17;
        std::vector<std::atomic<int>> hits(tasks);
        pool.run(tasks, 2 + round % 2, [&](int k) {
            if (k == round % tasks && round % 5 == 0) { // busy (asleep, the guard would step in)
                const auto end = std::chrono::steady_clock::now() + std::chrono::microseconds(50);
                while (std::chrono::steady_clock::now() < end) {
                }
            }
            hits[k].fetch_add(1);
        });
        for (int k = 0; k < tasks; ++k) ASSERT_EQ(hits[k].load(), 1) << round << " " << k;
    }
}

TEST(WorkerPool, OneThreadRunsOnTheCaller) {
    WorkerPool pool;
    const auto me = std::this_thread::get_id();
    pool.run(10, 1, [&](int) { EXPECT_EQ(std::this_thread::get_id(), me); });
    EXPECT_EQ(pool.helpers(), 0);
}

TEST(WorkerPool, NestedAndConcurrentCallsFinish) {
    WorkerPool pool;
    std::atomic<int> total{0};
    pool.run(4, 2, [&](int) { pool.run(8, 2, [&](int) { total.fetch_add(1); }); });
    EXPECT_EQ(total.load(), 32);
    total = 0;
    std::vector<std::jthread> callers;
    for (int c = 0; c < 3; ++c)
        callers.emplace_back([&] {
            for (int r = 0; r < 50; ++r) pool.run(16, 2, [&](int) { total.fetch_add(1); });
        });
    callers.clear(); // joins
    EXPECT_EQ(total.load(), 3 * 50 * 16);
}

TEST(WorkerPool, AnExceptionReachesTheCaller) {
    WorkerPool pool;
    std::atomic<int> ran{0};
    EXPECT_THROW(pool.run(64, 2,
                          [&](int k) {
                              ran.fetch_add(1);
                              if (k == 5) throw std::runtime_error("task 5");
                          }),
                 std::runtime_error);
    EXPECT_LE(ran.load(), 64);
    std::atomic<int> after{0};
    pool.run(10, 2, [&](int) { after.fetch_add(1); }); // still usable
    EXPECT_EQ(after.load(), 10);
}

TEST(WorkerPool, HandoutIsAPermutationAcrossRuns) {
    for (int tasks = 1; tasks <= 100; ++tasks) {
        for (int threads = 1; threads <= 70; ++threads) {
            std::vector<int> seen(tasks, 0);
            for (int h = 0; h < tasks; ++h) {
                const int k = WorkerPool::handout_task(h, tasks, threads);
                ASSERT_TRUE(k >= 0 && k < tasks) << tasks << " " << threads << " " << h;
                ASSERT_EQ(seen[k]++, 0) << tasks << " " << threads << " " << h;
                if (threads == 1) {
                    ASSERT_EQ(k, h);
                }
            }
        }
    }
    // 16 tasks for 2 threads: runs 0..7 and 8..15, handed out alternately.
    std::vector<int> order;
    for (int h = 0; h < 16; ++h) order.push_back(WorkerPool::handout_task(h, 16, 2));
    EXPECT_EQ(order, (std::vector<int>{0, 8, 1, 9, 2, 10, 3, 11, 4, 12, 5, 13, 6, 14, 7, 15}));
    order.clear();
    for (int h = 0; h < 7; ++h) order.push_back(WorkerPool::handout_task(h, 7, 3));
    EXPECT_EQ(order, (std::vector<int>{0, 3, 6, 1, 4, 2, 5})); // runs 0-2, 3-5, 6
}

// The contention guard: a call whose wall time exceeds its threads' CPU time in the tasks (a
// helper that sleeps in its task, as one preempted by another process does) sends the next
// calls to the caller alone, for WorkerPool::solo_start, after which the helpers are tried
// again.
TEST(WorkerPool, ALateHelperSendsTheNextCallsToTheCallerAlone) {
    using namespace std::chrono_literals;
    WorkerPool pool;
    const auto me = std::this_thread::get_id();
    // The caller's tasks take 1 ms, a helper's 40 ms, asleep. Repeated until a helper took a
    // task (one that wakes after the caller ran them all need not slow the call).
    for (int attempt = 0; attempt < 20 && !pool.solo(); ++attempt) {
        std::atomic<int> theirs{0};
        pool.run(8, 2, [&](int) {
            if (std::this_thread::get_id() == me) {
                std::this_thread::sleep_for(1ms);
            } else {
                theirs.fetch_add(1);
                std::this_thread::sleep_for(40ms);
            }
        });
        if (theirs.load() > 0) {
            EXPECT_TRUE(pool.solo());
        }
    }
    ASSERT_TRUE(pool.solo());
    std::atomic<int> elsewhere{0};
    pool.run(64, 2, [&](int) {
        if (std::this_thread::get_id() != me) elsewhere.fetch_add(1);
    });
    EXPECT_EQ(elsewhere.load(), 0);
    std::this_thread::sleep_for(WorkerPool::solo_start + 20ms);
    EXPECT_FALSE(pool.solo());
}
