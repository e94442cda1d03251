// Two one-sided tests (Schuirmann 1987) within a relative margin: the statistics by hand, the
// deterministic cases, the smallest claimable margin, and the size at the margin by
// simulation (judged with a Clopper–Pearson interval; Verity::stats has no name hash, so the
// seed is a fixed number).
#include <gtest/gtest.h>
#include <verity/stats/equivalence.h>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace verity::validation {
namespace {

TEST(Equivalence, OneSidedPValuesByHand) {
  // A: mean 1, V_A = 0.0004 (s² = 0.004, n = 10); B: mean 1.02, V_B = 0.0004. Margin 0.05:
  // lower bound 0.95: t_L = (1.02 − 0.95)/√(0.0004 + 0.95² 0.0004), upper 1.05:
  // t_U = (1.05 − 1.02)/√(0.0004 + 1.05² 0.0004).
  const MeanEstimate a = sampleMean(1.0, 0.004, 10), b = sampleMean(1.02, 0.004, 10);
  const EquivalenceResult r = relativeEquivalenceTest(a, b, 0.05);
  const auto p = [&](double x, double difference) {
    const double va = x * x * a.variance, vb = b.variance;
    const double df = (va + vb) * (va + vb) / (va * va / 9 + vb * vb / 9);
    const boost::math::students_t t(df);
    return boost::math::cdf(boost::math::complement(t, difference / std::sqrt(va + vb)));
  };
  EXPECT_NEAR(r.pLower, p(0.95, 1.02 - 0.95), 1e-12);
  EXPECT_NEAR(r.pUpper, p(1.05, 1.05 - 1.02), 1e-12);
  EXPECT_EQ(r.p, std::max(r.pLower, r.pUpper));
  EXPECT_LT(r.pLower, r.pUpper);  // B is nearer the upper bound
}

TEST(Equivalence, DeterministicTilesPassExactlyInsideTheMargin) {
  const MeanEstimate zero{0, 0, 0};
  EXPECT_EQ(relativeEquivalenceTest(zero, zero, 0.01).p, 0);  // black on both sides
  EXPECT_EQ(relativeEquivalenceTest({1, 0, 0}, {1.01, 0, 0}, 0.02).p, 0);
  EXPECT_EQ(relativeEquivalenceTest({1, 0, 0}, {1.03, 0, 0}, 0.02).p, 1);
  EXPECT_TRUE(relativeEquivalenceTest({1, 0, 0}, {1.03, 0, 0}, 0.02).deterministic);
}

TEST(Equivalence, ClaimableMarginIsWhereTheTestStartsToPass) {
  const MeanEstimate a = sampleMean(1.0, 0.004, 10), b = sampleMean(1.02, 0.004, 10);
  const double m = claimableMargin(a, b, 0.05);
  EXPECT_GT(m, 0.02);
  EXPECT_LE(relativeEquivalenceTest(a, b, m).p, 0.05);
  EXPECT_GT(relativeEquivalenceTest(a, b, m - 1e-5).p, 0.05);
  EXPECT_EQ(claimableMargin({1, 0, 0}, {1, 0, 0}, 0.05), 0);
  // A whose mean is not clearly above 0 bounds no ratio: no margin below 1.
  EXPECT_TRUE(std::isinf(claimableMargin(sampleMean(0.01, 1, 4), sampleMean(0.01, 1, 4), 0.05)));
}

// At a true ratio 1 + δ, equivalence within δ must be claimed with probability at most β.
// 4,000 simulated pairs of 8 normal values each (df 14), their standard error a quarter of the
// margin, so that the lower test always passes and the upper one alone decides: its rate is
// then β (exact for normal data up to the Satterthwaite approximation). The 99%
// Clopper–Pearson interval of the rate must reach down to β = 0.05; the rate must also not be
// far below β (a test that never claims equivalence would pass the first check).
TEST(Equivalence, SizeAtTheMarginIsAtMostTheLevel) {
  std::mt19937_64 random(37);  // fixed: the number, the first seed tried
  std::normal_distribution<double> normal;
  constexpr int kTrials = 4000, kSamples = 8;
  constexpr double kMargin = 0.1, kLevel = 0.05;
  int claimed = 0;
  for (int trial = 0; trial < kTrials; ++trial) {
    MeanEstimate e[2];
    for (int side = 0; side < 2; ++side) {
      const double mu = side == 0 ? 1.0 : 1 + kMargin;
      double sum = 0, squares = 0;
      for (int i = 0; i < kSamples; ++i) {
        const double x = mu + 0.05 * normal(random);
        sum += x;
        squares += x * x;
      }
      const double mean = sum / kSamples;
      e[side] = sampleMean(mean, (squares - kSamples * mean * mean) / (kSamples - 1), kSamples);
    }
    claimed += relativeEquivalenceTest(e[0], e[1], kMargin).p <= kLevel;
  }
  const double lower =
      boost::math::binomial_distribution<>::find_lower_bound_on_p(kTrials, claimed, 0.005);
  EXPECT_LE(lower, kLevel) << claimed << " of " << kTrials << " claimed equivalence";
  EXPECT_GT(claimed, kTrials * kLevel / 3) << "the test is far more conservative than expected";
}

TEST(Equivalence, BadInputIsRefused) {
  EXPECT_THROW(relativeEquivalenceTest({1, 0, 0}, {1, 0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(relativeEquivalenceTest({1, 0, 0}, {1, 0, 0}, -0.1), std::invalid_argument);
  EXPECT_THROW(claimableMargin({1, 0, 0}, {1, 0, 0}, 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace verity::validation
