// A oneTBB task arena of a given number of worker threads, 0 meaning all cores: the parallel
// loops run through execute() use that many threads at most. TBB caps its workers at the core
// count unless a global_control raises the cap, so an explicit count above it
// (oversubscription, tests of 3 threads on 2 cores) holds one while the arena lives and still
// gets its threads.
#pragma once

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <optional>
#include <utility>

namespace verity {

class ThreadArena {
 public:
  explicit ThreadArena(int threads);

  // f() on the arena's threads, returning what it returns (exceptions propagate).
  template <class F>
  decltype(auto) execute(F&& f) {
    return arena_.execute(std::forward<F>(f));
  }

 private:
  std::optional<tbb::global_control> allowThreads_;
  tbb::task_arena arena_;
};

}  // namespace verity
