#include "validation/compare/round_decision.h"

#include <algorithm>
#include <stdexcept>

namespace verity::validation {

std::string verdictName(Verdict v) {
  switch (v) {
    case Verdict::Equivalent:
      return "EQUIVALENT";
    case Verdict::Differ:
      return "DIFFER";
    case Verdict::Undecided:
      break;
  }
  return "UNDECIDED";
}

RoundDecision decideRound(const ComparisonResult& comparison, double margin,
                          double equivalenceLevel) {
  if (!(equivalenceLevel > 0 && equivalenceLevel < 0.5))
    throw std::invalid_argument("decideRound: equivalence level not in (0, 0.5)");
  RoundDecision d;
  d.differLevel = comparison.options.alpha;
  d.equivalenceLevel = equivalenceLevel;
  for (const TileTest& t : comparison.tests) {
    d.equivalence.push_back(relativeEquivalenceTest(t.pooled.a, t.pooled.b, margin));
    d.equivalentTests += d.equivalence.back().p <= equivalenceLevel;
  }
  if (comparison.differ)
    d.verdict = Verdict::Differ;
  else if (d.allEquivalent())
    d.verdict = Verdict::Equivalent;
  return d;
}

std::vector<size_t> undecidedTests(const RoundDecision& decision) {
  std::vector<size_t> out;
  for (size_t i = 0; i < decision.equivalence.size(); ++i)
    if (decision.equivalence[i].p > decision.equivalenceLevel) out.push_back(i);
  return out;
}

double claimableImageMargin(const ComparisonResult& comparison, const RoundDecision& decision) {
  double margin = 0;
  for (const TileTest& t : comparison.tests)
    margin = std::max(margin, claimableMargin(t.pooled.a, t.pooled.b, decision.equivalenceLevel));
  return margin;
}

}  // namespace verity::validation
