// The referee: renders two sides (or one side against a baseline's moments) in rounds until
// their images DIFFER or are EQUIVALENT within a relative margin, or the budget ends
// (INCONCLUSIVE).
//
// Rounds. Each side starts with `initialRenders` renders and doubles its count each round, up
// to `maxRenders`: K rounds are planned. Render i of side A has seed `seed + 2i`, of side B
// `seed + 2i + 1`, so no two renders share a seed. A baseline is side A, fixed.
//
// Levels across rounds. Round k is look k of K of two sequential tests, each spending its
// level `alpha` by a Lan–DeMets spending function over the looks' fraction k/K
// (verity/stats/alpha_spending.h):
// - DIFFER: validation/compare's per-tile Welch tests with Holm's procedure at the level α_k
//   spent at look k, so that the probability of a false DIFFER over all rounds is at most
//   Σ α_k = alpha (Bonferroni over the looks);
// - EQUIVALENT: two one-sided tests per tile and channel at the level β_k = α_k
//   (intersection-union: no correction over the tiles), so that the probability of a false
//   EQUIVALENT (some tile's true relative difference at least the margin) over all rounds is
//   at most alpha.
// A time budget (`maxSeconds`) that ends the rounds early spends less than alpha.
#pragma once

#include <verity/stats/alpha_spending.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "validation/compare/image_comparison.h"
#include "validation/compare/round_decision.h"
#include "validation/referee/render_source.h"
#include "validation/referee/tile_moments.h"

namespace verity::validation {

struct RefereeOptions {
  int tileSize = 16;
  double alpha = 0.01;   // the false-DIFFER and the false-EQUIVALENT level, over all rounds
  double margin = 0.01;  // relative to side A's expectation
  int initialRenders = 4;
  int maxRenders = 64;    // per side
  double maxSeconds = 0;  // no new round once this much time has passed; 0: no limit
  SpendingFunction spending = SpendingFunction::Pocock;
  std::string layer;  // the EXR layer of R, G and B (rgb_channels.h)
  uint64_t seed = 0;
};

// Throws VerityError naming the option (--tile, --alpha, --margin, --initial-renders,
// --max-renders, --max-seconds).
void checkRefereeOptions(const RefereeOptions& options);

// The renders each side has after each round: initialRenders doubling, the last capped at
// maxRenders.
std::vector<int> renderSchedule(const RefereeOptions& options);

uint64_t renderSeed(uint64_t seed, Side side, int index);

// The levels round `round` (0 ≤ round < K = renderSchedule(options).size()) spends: α_k of
// options.spending at look k = round + 1 of K, for DIFFER's Holm procedure and for the
// equivalence test's TOSTs alike (std::invalid_argument for a round outside). referee()
// decides by them; the calibrations test by them.
struct RoundLevels {
  double differ = 0, equivalence = 0;
};
RoundLevels roundLevels(const RefereeOptions& options, int round);

struct RoundRecord {
  int rendersA = 0, rendersB = 0;
  double seconds = 0;  // since the referee started, at the round's decision
  RoundDecision decision;
  int rejections = 0;  // Holm's, at the round's DIFFER level
};

struct RefereeResult {
  Verdict verdict = Verdict::Undecided;  // Undecided at the end: INCONCLUSIVE
  std::string stopReason;                // why an INCONCLUSIVE result stopped
  int plannedRounds = 0;
  std::vector<RoundRecord> rounds;
  ComparisonResult comparison;  // the last round's tests
  // For INCONCLUSIVE: the tests whose TOST did not pass, and the margin every test passes at
  // the last round's level (claimableImageMargin).
  std::vector<size_t> undecided;
  double claimableMargin = 0;
  TileMoments a, b;

  std::string verdictName() const;  // EQUIVALENT, DIFFER or INCONCLUSIVE
};

// `baseline`, when given, is side A (with at least 2 renders and options.tileSize). Throws
// VerityError for a failing render, a render of another size than the other side's (naming
// its file) or without R, G and B.
RefereeResult referee(RenderSource& source, const RefereeOptions& options,
                      const TileMoments* baseline = nullptr);

}  // namespace verity::validation

namespace verity::validation {

// A baseline's side: options.maxRenders renders of side A (seeds as in referee()), at once.
TileMoments renderBaselineSide(RenderSource& source, const RefereeOptions& options);

}  // namespace verity::validation
