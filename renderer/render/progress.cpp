#include "render/progress.h"

#include <fmt/format.h>

#include <string>

namespace verity {

Progress::Progress(uint64_t totalWork, bool enabled)
    : total_(std::max<uint64_t>(totalWork, 1)),
      enabled_(enabled),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

void Progress::advance(uint64_t work) {
  done_ += work;
  if (!enabled_) return;
  std::unique_lock lock(drawMutex_, std::try_to_lock);
  if (!lock) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - lastDraw_ < std::chrono::milliseconds(200)) return;
  lastDraw_ = now;
  draw(false);
}

void Progress::finish() {
  if (!enabled_) return;
  std::lock_guard lock(drawMutex_);
  draw(true);
  fmt::print(stderr, "\n");
}

void Progress::draw(bool final) {
  const double fraction = std::min(1.0, static_cast<double>(done_) / total_);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const int width = 40;
  const int filled = static_cast<int>(fraction * width);
  std::string bar(filled, '=');
  if (filled < width) bar += '>' + std::string(width - filled - 1, ' ');
  std::string eta = "--";
  if (fraction > 0) eta = fmt::format("{:.1f}s", elapsed * (1 - fraction) / fraction);
  fmt::print(stderr, "\r[{}] {:5.1f}%  elapsed {:.1f}s  ETA {}{}", bar, 100 * fraction, elapsed,
             final ? "0.0s" : eta, "   ");
}

}  // namespace verity
