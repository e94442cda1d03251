// A comparison's result for people (a summary) and for programs (JSON).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "validation/compare/image_comparison.h"

namespace verity::validation {

// Tiles tested, smallest p, the Holm decision, the KS uniformity p-value, the detectable
// bias, the `worstCount` tests with the smallest p (position, channel, means, relative
// difference), warnings and the verdict.
std::string comparisonSummary(const ComparisonResult& result, size_t worstCount = 5);

// Everything in the result, every test included.
nlohmann::json comparisonJson(const ComparisonResult& result);

}  // namespace verity::validation
