// Runs a check on the number of threads its options ask for (CheckOptions::threads).
#pragma once

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <stdexcept>
#include <utility>

namespace verity::chi2 {

// f() in a task arena of `threads` threads (the calling thread among them), or in the
// current one for 0. With 1 every task of f runs on the calling thread.
template <class F>
auto onThreads(int threads, F&& f) {
  if (threads < 0)
    throw std::invalid_argument(
        fmt::format("CheckOptions::threads = {}: must be 0 (every core) or more", threads));
  if (threads == 0) return f();
  tbb::task_arena arena(threads);
  return arena.execute(std::forward<F>(f));
}

}  // namespace verity::chi2
