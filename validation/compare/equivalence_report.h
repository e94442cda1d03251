// The equivalence part of a comparison's report (round_decision.h's two one-sided tests), for
// people and for programs: what `verity compare --margin` adds, and the referee's reports.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "validation/compare/round_decision.h"

namespace verity::validation {

// A claimable margin (claimableImageMargin): "±0.0123", or "none below 1" for infinity.
std::string marginText(double margin);
// The same for JSON, which has no infinity: "inf".
nlohmann::json marginJson(double margin);

// Margin, level, whether every test passed (EQUIVALENT, or "not shown"), the claimable margin,
// and each test's one-sided p-values.
nlohmann::json equivalenceJson(const ComparisonResult& comparison, const RoundDecision& decision,
                               double margin);
std::string equivalenceSummary(const ComparisonResult& comparison, const RoundDecision& decision,
                               double margin);

}  // namespace verity::validation
