// What an adapter's check returns: the sampling test with its two statistical verdicts
// (chi-square on the shape, pdf integral on the normalisation) and the per-sample audit,
// plus a list of what failed, by name, to print or assert on.
#pragma once

#include <string>
#include <vector>

#include "sampling_check.h"

namespace verity::chi2 {

// Each check runs two statistical tests (chi-square and pdf integral): a caller that runs
// n checks at a family-wise level α uses sidakLevel(α, kStatisticalTestsPerCheck · n).
inline constexpr int kStatisticalTestsPerCheck = 2;

struct CheckResult {
  TestResult test;
  long long deltaSamples = 0;  // delta-lobe samples, counted and not histogrammed

  bool passed() const { return test.passed(); }
  // "chi-square", "pdf integral", "samples outside the domain" and the audit's defects
  // ("weight != eval*cos/pdf", "reciprocity", ...: defectName()); empty when it passed.
  std::vector<std::string> failures() const;
  bool failed(const std::string& check) const;
  std::string report() const;
};

}  // namespace verity::chi2
