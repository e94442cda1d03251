#include <fmt/format.h>
#include <verity/chi2/phase_times.h>

#include <iterator>

namespace verity::chi2 {

const char* phaseName(Phase phase) {
  static const char* names[] = {"cells",   "quadrature",  "drawing",    "audit",
                                "binning", "delta lobes", "statistics", "figure"};
  static_assert(std::size(names) == static_cast<size_t>(Phase::Count));
  return names[static_cast<int>(phase)];
}

double PhaseTimes::total() const {
  double t = 0;
  for (double s : seconds_) t += s;
  return t;
}

std::string PhaseTimes::describe() const {
  std::string s;
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p) {
    if (seconds_[p] <= 0) continue;
    s += fmt::format("{}{} {:.3f} s", s.empty() ? "" : ", ", phaseName(static_cast<Phase>(p)),
                     seconds_[p]);
  }
  return s.empty() ? "no phase timed" : s;
}

}  // namespace verity::chi2
