#include "render/interrupt.h"

#include <csignal>

namespace verity {

namespace {
std::atomic<bool> interrupted{false};
// Counted per signal: a Ctrl-C under mpirun reaches a rank twice, as SIGINT from the terminal
// and as SIGTERM from mpirun, and that is still one request to stop.
std::atomic<bool> seenInterrupt{false}, seenTerminate{false};

extern "C" void onInterrupt(int signal) {
  std::atomic<bool>& seen = signal == SIGTERM ? seenTerminate : seenInterrupt;
  interrupted = true;
  if (seen.exchange(true)) {
    std::signal(signal, SIG_DFL);
    std::raise(signal);
  }
}
}  // namespace

InterruptGuard::InterruptGuard(bool alsoTerminate) : alsoTerminate_(alsoTerminate) {
  interrupted = false;
  seenInterrupt = false;
  seenTerminate = false;
  std::signal(SIGINT, onInterrupt);
  if (alsoTerminate_) std::signal(SIGTERM, onInterrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, SIG_DFL);
  if (alsoTerminate_) std::signal(SIGTERM, SIG_DFL);
}

const std::atomic<bool>& InterruptGuard::flag() {
  return interrupted;
}

}  // namespace verity
