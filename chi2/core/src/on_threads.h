// Runs a check on the number of threads its options ask for (CheckOptions::threads).
#pragma once

#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <stdexcept>

namespace verity::chi2 {

// For options.threads other than 0: check of a copy of the options whose threads is 0 (the
// check itself), in a task arena of options.threads threads, the calling thread among them
// (with 1, every task of the check runs on it).
template <class Options, class Check>
auto onThreads(const Options& options, Check&& check) {
  if (options.threads < 0)
    throw std::invalid_argument(
        fmt::format("CheckOptions::threads = {}: must be 0 (every core) or more", options.threads));
  Options inside = options;
  inside.threads = 0;
  tbb::task_arena arena(options.threads);
  return arena.execute([&] { return check(inside); });
}

}  // namespace verity::chi2
