#include "commands/check_progress_display.h"

#include <fmt/format.h>

#include <chrono>
#include <string>

namespace verity {

namespace {

// A check shorter than this prints nothing; a longer one is redrawn this often.
constexpr std::chrono::milliseconds kQuiet{2000}, kRedraw{250};

std::string describe(const chi2::CheckProgress& p) {
  const chi2::Phase phase = p.phase;
  if (phase == chi2::Phase::Count) return "";
  const long long checks = p.checks;
  const std::string of = checks > 0 ? fmt::format("check {} of {}, ", p.check.load(), checks) : "";
  if (phase == chi2::Phase::Drawing) {
    const long long samples = p.samples, drawn = p.drawn;
    return of + fmt::format("drawing and auditing samples: {} of {} ({:.0f}%)", drawn, samples,
                            samples > 0 ? 100.0 * drawn / samples : 0.0);
  }
  return of + chi2::phaseName(phase);
}

}  // namespace

CheckProgressDisplay::CheckProgressDisplay(const chi2::CheckProgress& progress, bool enabled)
    : progress_(progress) {
  if (enabled) thread_ = std::thread([this] { show(); });
}

CheckProgressDisplay::~CheckProgressDisplay() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_.notify_one();
  thread_.join();
  if (drawn_) fmt::print(stderr, "\r\033[K");
}

void CheckProgressDisplay::show() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_);
  if (stop_.wait_for(lock, kQuiet, [this] { return stopping_; })) return;
  do {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string what = describe(progress_);
    if (!what.empty()) {
      fmt::print(stderr, "\r\033[K  chi2: {}, {:.0f} s", what, elapsed);
      std::fflush(stderr);
      drawn_ = true;
    }
  } while (!stop_.wait_for(lock, kRedraw, [this] { return stopping_; }));
}

}  // namespace verity
