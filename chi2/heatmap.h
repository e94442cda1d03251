// PNG heatmaps of a test's histogram: observed counts, expected counts (one shared scale)
// and the standardised difference (O − E)/√E (blue negative, red positive, ±5 saturates).
#pragma once

#include <string>
#include <vector>

#include "chi2/sampling_check.h"

namespace verity::chi2 {

// Writes PREFIX_observed.png, PREFIX_expected.png and PREFIX_difference.png; returns the
// paths written.
std::vector<std::string> writeHeatmaps(const TestResult& result, const std::string& prefix);

}  // namespace verity::chi2
