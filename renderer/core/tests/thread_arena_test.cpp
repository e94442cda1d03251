// ThreadArena runs its work on the threads asked for: one runs a parallel loop alone, and one
// more than the machine's cores gets them all at once (TBB caps its workers at the core count
// unless a global_control raises the cap; without it the loop reaches the core count only).
#include "core/thread_arena.h"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>

namespace verity {
namespace {

// The most tasks of a loop of `tasks` found running at once: each waits, up to `patience`,
// until all of them have started, so that as many run at once as there are threads.
int tasksAtOnce(ThreadArena& arena, int tasks, std::chrono::milliseconds patience) {
  std::atomic<int> started{0}, running{0}, most{0};
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<int>(0, tasks, 1),
        [&](const tbb::blocked_range<int>&) {
          ++started;
          const int now = ++running;
          int seen = most.load();
          while (seen < now && !most.compare_exchange_weak(seen, now)) {
          }
          const auto until = std::chrono::steady_clock::now() + patience;
          while (started.load() < tasks && std::chrono::steady_clock::now() < until)
            std::this_thread::yield();
          --running;
        },
        tbb::simple_partitioner());
  });
  return most.load();
}

TEST(ThreadArena, OneThreadRunsTheLoopAlone) {
  ThreadArena arena(1);
  EXPECT_EQ(arena.execute([] { return tbb::this_task_arena::max_concurrency(); }), 1);
  EXPECT_EQ(tasksAtOnce(arena, 2, std::chrono::milliseconds(200)), 1);
}

TEST(ThreadArena, MoreThreadsThanCoresAllRunAtOnce) {
  const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency())) + 1;
  ThreadArena arena(threads);
  EXPECT_EQ(arena.execute([] { return tbb::this_task_arena::max_concurrency(); }), threads);
  EXPECT_EQ(tasksAtOnce(arena, threads, std::chrono::seconds(20)), threads);
}

}  // namespace
}  // namespace verity
