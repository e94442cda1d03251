#include <fmt/format.h>
#include <verity/chi2/audit.h>

#include <cmath>
#include <iterator>
#include <limits>

namespace verity::chi2 {

const char* defectName(Defect d) {
  static const char* names[] = {
      "non-finite value",       "negative value", "weight != eval*cos/pdf",
      "sample pdf != pdf()",    "reciprocity",    "direction not a unit vector",
      "value of the wrong size"};
  static_assert(std::size(names) == static_cast<size_t>(Defect::Count));
  return names[static_cast<int>(d)];
}

bool relativelyClose(double a, double b, double rel) {
  return std::fabs(a - b) <= rel * (std::max(std::fabs(a), std::fabs(b)) + kAbsoluteFloor);
}

double ratioDeviation(double a, double b) {
  if (b == 0) return a == 0 ? 0 : std::numeric_limits<double>::infinity();
  return std::fabs(a / b - 1);
}

void Audit::record(Defect d, const std::string& example) {
  const int i = static_cast<int>(d);
  if (counts_[i]++ == 0) examples_[i] = example;
}

void Audit::record(Defect d, double deviation, const std::string& example) {
  record(d, example);
  const int i = static_cast<int>(d);
  // The first of equal deviations, so that the merged audit does not depend on timing.
  if (deviation > worst_[i] || worstExamples_[i].empty()) {
    worst_[i] = deviation;
    worstExamples_[i] = example;
  }
}

void Audit::merge(const Audit& other) {
  seconds_ += other.seconds_;
  for (int i = 0; i < kKinds; ++i) {
    if (counts_[i] == 0 && other.counts_[i] > 0) examples_[i] = other.examples_[i];
    counts_[i] += other.counts_[i];
    if (!other.worstExamples_[i].empty() &&
        (other.worst_[i] > worst_[i] || worstExamples_[i].empty())) {
      worst_[i] = other.worst_[i];
      worstExamples_[i] = other.worstExamples_[i];
    }
  }
}

bool Audit::clean() const {
  for (long long c : counts_)
    if (c) return false;
  return true;
}

std::string Audit::describe() const {
  if (clean()) return "per-sample checks: clean";
  std::string s = "per-sample checks FAILED:";
  for (int i = 0; i < kKinds; ++i) {
    if (!counts_[i]) continue;
    s += fmt::format("\n    {}: {} time(s), first: {}", defectName(static_cast<Defect>(i)),
                     counts_[i], examples_[i]);
    if (!worstExamples_[i].empty())
      s += fmt::format("\n      worst |ratio - 1| = {:.3g}: {}", worst_[i], worstExamples_[i]);
  }
  return s;
}

}  // namespace verity::chi2
