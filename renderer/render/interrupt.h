// Ctrl-C handling for long jobs: the first SIGINT asks the job to stop after the work in
// flight (so finished work is written); a second one ends the process at once.
#pragma once

#include <atomic>

namespace verity {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static const std::atomic<bool>& flag();
};

}  // namespace verity
