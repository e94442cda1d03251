// Ctrl-C handling for long jobs: the first SIGINT asks the job to stop after the work in
// flight (so finished work is written); a second one ends the process at once. Under mpirun,
// whose answer to Ctrl-C is SIGTERM to every rank (then SIGKILL a few seconds later), SIGTERM
// is taken the same way.
#pragma once

#include <atomic>

namespace verity {

class InterruptGuard {
 public:
  // `alsoTerminate`: SIGTERM too (ranks of an MPI job).
  explicit InterruptGuard(bool alsoTerminate = false);
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  static const std::atomic<bool>& flag();

 private:
  bool alsoTerminate_;
};

}  // namespace verity
