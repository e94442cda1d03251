// The referee's results for people (a summary) and for programs (JSON, documented in
// docs/referee.md); the equivalence part of a comparison's report is equivalence_report.h.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "validation/referee/referee.h"

namespace verity::validation {

// The verdict, the options, each round (renders, seconds, levels, decision) and the last
// round's comparison with every tile's Welch and TOST results.
nlohmann::json refereeJson(const RefereeResult& result, const RefereeOptions& options);
// The rounds, the verdict and, for INCONCLUSIVE, the undecided tiles and the claimable margin.
std::string refereeSummary(const RefereeResult& result, const RefereeOptions& options);

}  // namespace verity::validation
