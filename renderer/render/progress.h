// A progress bar with elapsed time and ETA on a terminal's stderr; silent otherwise.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>

namespace verity {

class Progress {
 public:
  Progress(uint64_t totalWork, bool enabled);
  // Thread-safe; redraws at most a few times per second.
  void advance(uint64_t work);
  void finish();

 private:
  void draw(bool final);

  uint64_t total_;
  std::atomic<uint64_t> done_{0};
  bool enabled_;
  std::mutex drawMutex_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace verity
