#include <fmt/format.h>
#include <verity/chi2/audit.h>

#include <algorithm>
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

double factorDeviation(double a, double b) {
  return std::max(ratioDeviation(a, b), ratioDeviation(b, a));
}

double deviationWithinFactor(double ratio, double spread) {
  if (ratio >= 1 || std::isinf(spread)) return spread;
  return spread / (1 + spread);
}

void Audit::record(Defect d, const std::string& example) {
  const int i = static_cast<int>(d);
  if (counts_[i]++ == 0) examples_[i] = example;
}

namespace {

// The larger deviation, the first of equal ones so that a merged audit does not depend on
// timing.
void keepWorst(double deviation, const std::string& example, double& worst, std::string& kept) {
  if (deviation > worst || kept.empty()) {
    worst = deviation;
    kept = example;
  }
}

}  // namespace

void Audit::record(Defect d, double deviation, double rounding, const std::string& example) {
  record(d, example);
  const int i = static_cast<int>(d);
  keepWorst(deviation, example, worst_[i], worstExamples_[i]);
  if (std::isnan(rounding)) return;  // not classified
  ++classified_[i];
  if (!(deviation <= rounding)) {
    ++beyond_[i];
    keepWorst(deviation, example, worstBeyond_[i], worstBeyondExamples_[i]);
  }
}

void Audit::merge(const Audit& other) {
  seconds_ += other.seconds_;
  for (int i = 0; i < kKinds; ++i) {
    if (counts_[i] == 0 && other.counts_[i] > 0) examples_[i] = other.examples_[i];
    counts_[i] += other.counts_[i];
    if (!other.worstExamples_[i].empty())
      keepWorst(other.worst_[i], other.worstExamples_[i], worst_[i], worstExamples_[i]);
    classified_[i] += other.classified_[i];
    beyond_[i] += other.beyond_[i];
    if (!other.worstBeyondExamples_[i].empty())
      keepWorst(other.worstBeyond_[i], other.worstBeyondExamples_[i], worstBeyond_[i],
                worstBeyondExamples_[i]);
  }
}

bool Audit::onlyRounding() const {
  if (clean()) return false;
  for (int i = 0; i < kKinds; ++i)
    if (counts_[i] && (worstExamples_[i].empty() || classified_[i] == 0 || beyond_[i] > 0))
      return false;
  return true;
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
    if (worstExamples_[i].empty()) continue;
    s += fmt::format("\n      worst |ratio - 1| = {:.3g}: {}", worst_[i], worstExamples_[i]);
    if (classified_[i] == 0) continue;
    const std::string of = classified_[i] == counts_[i]
                               ? fmt::format("{}", counts_[i])
                               : fmt::format("{} classified (of {})", classified_[i], counts_[i]);
    if (beyond_[i] == 0)
      s += fmt::format("\n      all {} within what rounding the directions give there", of);
    else
      s += fmt::format(
          "\n      {} of {} beyond what rounding gives there, the worst |ratio - 1| = "
          "{:.3g}: {}",
          beyond_[i], of, worstBeyond_[i], worstBeyondExamples_[i]);
  }
  return s;
}

}  // namespace verity::chi2
