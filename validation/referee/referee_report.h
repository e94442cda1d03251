// The referee's results for people (a summary) and for programs (JSON, documented in
// docs/referee.md), and the equivalence part that `verity compare --margin` adds to its report.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "validation/referee/referee.h"

namespace verity::validation {

// Margin, level, whether every test passed (EQUIVALENT, or "not shown"), the claimable margin,
// and each test's one-sided p-values.
nlohmann::json equivalenceJson(const ComparisonResult& comparison, const RoundDecision& decision,
                               double margin);
std::string equivalenceSummary(const ComparisonResult& comparison, const RoundDecision& decision,
                               double margin);

// The verdict, the options, each round (renders, seconds, levels, decision) and the last
// round's comparison with every tile's Welch and TOST results.
nlohmann::json refereeJson(const RefereeResult& result, const RefereeOptions& options);
// The rounds, the verdict and, for INCONCLUSIVE, the undecided tiles and the claimable margin.
std::string refereeSummary(const RefereeResult& result, const RefereeOptions& options);

}  // namespace verity::validation
