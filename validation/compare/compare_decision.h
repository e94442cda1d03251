// What `verity compare` decides on two sides and reports: the per-tile comparison
// (image_comparison.h) and, with a margin, the referee's equivalence test at the same level
// (round_decision.h; one look, so no alpha spending), with the summary and the JSON of both.
// The command and the Python module's verity.compare run this one function.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "validation/compare/image_comparison.h"
#include "validation/compare/round_decision.h"

namespace verity::validation {

struct CompareDecision {
  ComparisonResult comparison;
  double margin = 0;                         // 0: no equivalence test
  std::optional<RoundDecision> equivalence;  // with a margin
  std::string summary;                       // comparisonSummary, then equivalenceSummary
  nlohmann::json json;                       // comparisonJson, with "equivalence"

  // DIFFER when Holm rejects a test; otherwise AGREE without a margin, and with one
  // EQUIVALENT when every test's TOST passes, else EQUIVALENCE NOT SHOWN.
  std::string verdict() const;
};

// The options and the margin, in [0, 1) (0: none); with a margin, two one-sided tests at
// options.alpha need it below 0.5. Throws VerityError naming the option.
void checkCompareOptions(const ComparisonOptions& options, double margin);

CompareDecision decideComparison(const ComparisonSide& a, const ComparisonSide& b,
                                 const ComparisonOptions& options, double margin);

}  // namespace verity::validation
