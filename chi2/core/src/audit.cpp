#include <fmt/format.h>
#include <verity/chi2/audit.h>

#include <cmath>

namespace verity::chi2 {

const char* defectName(Defect d) {
  static const char* names[] = {
      "non-finite value",    "negative value", "weight != eval*cos/pdf",
      "sample pdf != pdf()", "reciprocity",    "direction not a unit vector"};
  return names[static_cast<int>(d)];
}

bool relativelyClose(double a, double b, double rel) {
  return std::fabs(a - b) <= rel * (std::max(std::fabs(a), std::fabs(b)) + kAbsoluteFloor);
}

void Audit::record(Defect d, const std::string& example) {
  const int i = static_cast<int>(d);
  if (counts_[i]++ == 0) examples_[i] = example;
}

void Audit::merge(const Audit& other) {
  for (int i = 0; i < static_cast<int>(Defect::Count); ++i) {
    if (counts_[i] == 0 && other.counts_[i] > 0) examples_[i] = other.examples_[i];
    counts_[i] += other.counts_[i];
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
  for (int i = 0; i < static_cast<int>(Defect::Count); ++i)
    if (counts_[i])
      s += fmt::format("\n    {}: {} time(s), first: {}", defectName(static_cast<Defect>(i)),
                       counts_[i], examples_[i]);
  return s;
}

}  // namespace verity::chi2
