// The referee's error rates across rounds, by simulation: 500 refereed decisions per case on
// the fake renderer's images (fake_images.h) made in the process, through the same round
// logic as `verity referee` (referee.h). Required, each judged by a 99% Clopper–Pearson
// interval of the rate over the 500 runs (its lower end must not exceed α):
// - false DIFFER ≤ α when A and B have the same expectations;
// - false EQUIVALENT ≤ α when the true relative bias equals the margin, in every tile or in
//   one channel of one tile only (the worst case of the intersection-union test: one test at
//   the margin, all others far inside).
// Normal and heavy-tailed (log-normal) pixels. Each case prints its decisions and the renders
// per side they took (docs/referee.md quotes them). Seeds fixed by the cases' names.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <string>

#include "core/hash.h"
#include "validation/referee/referee.h"
#include "validation/referee/tests/fake_images.h"

namespace verity::validation {
namespace {

constexpr int kRuns = 500;
constexpr double kAlpha = 0.05;

struct Case {
  std::string name;
  bool heavy = false;
  double margin = 0.05;
  double biasInMargins = 0;  // the true relative bias of B, in margins
  int biasedTiles = -1;      // −1: every tile
  int biasedChannels = 3;
};

struct Tally {
  int equivalent = 0, differ = 0, inconclusive = 0;
  double meanRenders = 0;  // per side, at the decision
  int maxRenders = 0;
};

Tally runCase(const Case& c) {
  testing::FakeScene a;
  a.heavyTails = c.heavy;
  a.noise = c.heavy ? 0.5 : 0.25;
  testing::FakeScene b = a;
  b.bias = c.biasInMargins * c.margin;
  b.biasedTiles = c.biasedTiles;
  b.biasedChannels = c.biasedChannels;
  testing::FakeRenderSource source(a, b);
  RefereeOptions options;
  options.tileSize = a.tileSize;
  options.alpha = kAlpha;
  options.margin = c.margin;
  options.initialRenders = 4;
  options.maxRenders = 256;
  Tally t;
  for (int run = 0; run < kRuns; ++run) {
    options.seed = hashString(c.name) + uint64_t(run) * 1000;
    const RefereeResult r = referee(source, options);
    t.equivalent += r.verdict == Verdict::Equivalent;
    t.differ += r.verdict == Verdict::Differ;
    t.inconclusive += r.verdict == Verdict::Undecided;
    t.meanRenders += r.rounds.back().rendersB / double(kRuns);
    t.maxRenders = std::max(t.maxRenders, r.rounds.back().rendersB);
  }
  std::printf("| %-28s | %4d | %4d | %4d | %6.1f |\n", c.name.c_str(), t.equivalent, t.differ,
              t.inconclusive, t.meanRenders);
  return t;
}

// The lower end of the 99% Clopper–Pearson interval of a rate of `count` in kRuns.
double lowerBound(int count) {
  return boost::math::binomial_distribution<>::find_lower_bound_on_p(kRuns, count, 0.005);
}

class Calibration : public ::testing::TestWithParam<bool> {};

TEST_P(Calibration, FalseDifferAtMostAlpha) {
  const bool heavy = GetParam();
  const Tally t =
      runCase({heavy ? "heavy, bias 0" : "normal, bias 0", heavy, heavy ? 0.1 : 0.05, 0});
  EXPECT_LE(lowerBound(t.differ), kAlpha) << t.differ << " of " << kRuns << " runs said DIFFER";
  // And it does decide: a referee that never said anything would pass the check above.
  EXPECT_GT(t.equivalent, kRuns * 3 / 4);
}

TEST_P(Calibration, FalseEquivalentAtTheMarginAtMostAlpha) {
  const bool heavy = GetParam();
  const double margin = heavy ? 0.1 : 0.05;
  const std::string kind = heavy ? "heavy" : "normal";
  for (bool one : {false, true}) {
    const Tally t = runCase({kind + ", bias = margin" + (one ? " in one test" : ""), heavy, margin,
                             1, one ? 1 : -1, one ? 1 : 3});
    EXPECT_LE(lowerBound(t.equivalent), kAlpha)
        << t.equivalent << " of " << kRuns << " runs said EQUIVALENT";
  }
}

// Not a requirement but the table of docs/referee.md: what each decision costs, and that the
// referee does decide (a referee that never decides would pass the two tests above).
TEST_P(Calibration, RendersPerDecision) {
  const bool heavy = GetParam();
  const double margin = heavy ? 0.1 : 0.05;
  const std::string kind = heavy ? "heavy" : "normal";
  const Tally half = runCase({kind + ", bias = margin/2", heavy, margin, 0.5});
  const Tally twice = runCase({kind + ", bias = 2 margins", heavy, margin, 2});
  // Half the margin is a difference too: DIFFER or EQUIVALENT are both right; it must decide.
  EXPECT_GT(half.equivalent + half.differ, kRuns * 9 / 10);
  EXPECT_GT(twice.differ, kRuns * 9 / 10);
}

INSTANTIATE_TEST_SUITE_P(Referee, Calibration, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "Heavy" : "Normal"; });

}  // namespace
}  // namespace verity::validation
