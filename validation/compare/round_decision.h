// One look of the referee: the decision on a round's comparison (validation/compare's per-tile
// Welch tests with Holm's procedure, at the DIFFER level this look spends) together with the
// equivalence of every tile and channel within the relative margin (two one-sided tests,
// verity/stats/equivalence.h, at the equivalence level this look spends).
//   DIFFER      Holm rejects any test: a difference is significant;
//   EQUIVALENT  otherwise, every test's TOST passes: by the intersection-union principle the
//               image is equivalent at the tests' level, with no correction for their number;
//   UNDECIDED   otherwise.
// DIFFER is checked first: a difference that is significant but within the margin is
// reported, since the renders then estimate different images.
#pragma once

#include <verity/stats/equivalence.h>

#include <string>
#include <vector>

#include "validation/compare/image_comparison.h"

namespace verity::validation {

enum class Verdict { Equivalent, Differ, Undecided };
std::string verdictName(Verdict v);  // EQUIVALENT, DIFFER, UNDECIDED

struct RoundDecision {
  Verdict verdict = Verdict::Undecided;
  double differLevel = 0, equivalenceLevel = 0;
  std::vector<EquivalenceResult> equivalence;  // per test of the comparison, same order
  int equivalentTests = 0;

  // The equivalence test's own decision, whatever DIFFER says: every test's TOST passes.
  bool allEquivalent() const { return equivalentTests == int(equivalence.size()); }
};

// `comparison` was decided at the DIFFER level (its options.alpha); margin in [0, 1),
// equivalenceLevel in (0, 0.5) (std::invalid_argument otherwise).
RoundDecision decideRound(const ComparisonResult& comparison, double margin,
                          double equivalenceLevel);

// Indices of the tests whose TOST did not pass.
std::vector<size_t> undecidedTests(const RoundDecision& decision);

// The largest over the tests of the smallest margin each passes at the round's equivalence
// level (claimableMargin): the margin the image could have been claimed equivalent within.
double claimableImageMargin(const ComparisonResult& comparison, const RoundDecision& decision);

}  // namespace verity::validation
