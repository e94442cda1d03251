#include "validation/compare/equivalence_report.h"

#include <fmt/format.h>

#include <cmath>

namespace verity::validation {

std::string marginText(double m) {
  return std::isfinite(m) ? fmt::format("±{:.4g}", m) : std::string("none below 1");
}

nlohmann::json marginJson(double m) {
  return std::isfinite(m) ? nlohmann::json(m) : nlohmann::json(m > 0 ? "inf" : "-inf");
}

nlohmann::json equivalenceJson(const ComparisonResult& comparison, const RoundDecision& decision,
                               double margin) {
  nlohmann::json tests = nlohmann::json::array();
  for (size_t i = 0; i < comparison.tests.size(); ++i) {
    const TileTest& t = comparison.tests[i];
    const EquivalenceResult& e = decision.equivalence[i];
    tests.push_back({{"tile", {t.tileX, t.tileY}},
                     {"channel", kChannelNames[t.channel]},
                     {"p_lower", e.pLower},
                     {"p_upper", e.pUpper},
                     {"p", e.p},
                     {"equivalent", e.p <= decision.equivalenceLevel}});
  }
  const bool all = decision.allEquivalent();
  return {{"margin", margin},
          {"level", decision.equivalenceLevel},
          {"verdict", all ? "EQUIVALENT" : "not shown"},
          {"equivalent_tests", decision.equivalentTests},
          {"claimable_margin", marginJson(claimableImageMargin(comparison, decision))},
          {"tests", tests}};
}

std::string equivalenceSummary(const ComparisonResult& comparison, const RoundDecision& decision,
                               double margin) {
  const bool all = decision.allEquivalent();
  return fmt::format(
      "equivalence within ±{} of A (two one-sided tests per tile and channel at level {}, "
      "intersection-union): {} of {} tests pass; {}; the smallest margin every test passes: "
      "{}\n",
      margin, decision.equivalenceLevel, decision.equivalentTests, comparison.tests.size(),
      all ? "EQUIVALENT" : "equivalence not shown",
      marginText(claimableImageMargin(comparison, decision)));
}

}  // namespace verity::validation
