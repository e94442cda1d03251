// A running chi-square check's phase on a terminal's stderr, once it has run a few seconds
// (a quick check prints nothing), and redrawn a few times a second until it ends; silent where
// stderr is not a terminal.
#pragma once

#include <verity/chi2/phase_times.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace verity {

class CheckProgressDisplay {
 public:
  // Shows `progress` while this object lives; `enabled` false shows nothing.
  CheckProgressDisplay(const chi2::CheckProgress& progress, bool enabled);
  CheckProgressDisplay(const CheckProgressDisplay&) = delete;
  CheckProgressDisplay& operator=(const CheckProgressDisplay&) = delete;
  // Stops and clears the line it drew.
  ~CheckProgressDisplay();

 private:
  void show();

  const chi2::CheckProgress& progress_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  bool drawn_ = false;
  std::thread thread_;
};

}  // namespace verity
