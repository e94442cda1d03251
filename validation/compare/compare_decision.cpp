#include "validation/compare/compare_decision.h"

#include <fmt/format.h>

#include "core/error.h"
#include "validation/compare/comparison_report.h"
#include "validation/compare/equivalence_report.h"

namespace verity::validation {

std::string CompareDecision::verdict() const {
  if (comparison.differ) return "DIFFER";
  if (!equivalence) return "AGREE";
  return equivalence->verdict == Verdict::Equivalent ? "EQUIVALENT" : "EQUIVALENCE NOT SHOWN";
}

void checkCompareOptions(const ComparisonOptions& options, double margin) {
  checkComparisonOptions(options);
  if (!(margin >= 0 && margin < 1))
    throw VerityError("", "--margin",
                      fmt::format("the relative margin must lie in [0, 1), not {}", margin));
  if (margin > 0 && options.alpha >= 0.5)
    throw VerityError("", "--alpha",
                      fmt::format("with --margin, two one-sided tests need a level below 0.5, "
                                  "not {}",
                                  options.alpha));
}

CompareDecision decideComparison(const ComparisonSide& a, const ComparisonSide& b,
                                 const ComparisonOptions& options, double margin) {
  checkCompareOptions(options, margin);
  CompareDecision d;
  d.margin = margin;
  d.comparison = compareSides(a, b, options);
  d.summary = comparisonSummary(d.comparison);
  d.json = comparisonJson(d.comparison);
  if (margin > 0) {
    d.equivalence = decideRound(d.comparison, margin, options.alpha);
    d.summary += equivalenceSummary(d.comparison, *d.equivalence, margin);
    d.json["equivalence"] = equivalenceJson(d.comparison, *d.equivalence, margin);
  }
  return d;
}

}  // namespace verity::validation
