// Welch's test against values computed by hand from its definition (Welch 1947;
// Satterthwaite 1946) and against printed critical values of Student's t.
#include <gtest/gtest.h>
#include <verity/stats/welch_t.h>

#include <cmath>
#include <stdexcept>

namespace verity::validation {
namespace {

TEST(Welch, SatterthwaiteDegreesOfFreedomByHand) {
  // s_A² = 4, n_A = 10: V_A = 0.4; s_B² = 9, n_B = 20: V_B = 0.45.
  // ν = 0.85² / (0.4²/9 + 0.45²/19) = 0.7225 / (0.0177778 + 0.0106579) = 25.40823.
  const WelchResult r = welchTest(sampleMean(1.0, 4.0, 10), sampleMean(2.0, 9.0, 20));
  EXPECT_NEAR(r.df, 25.40823, 1e-5);
  EXPECT_NEAR(r.t, 1.0 / std::sqrt(0.85), 1e-12);
  EXPECT_FALSE(r.deterministic);
}

TEST(Welch, EqualVariancesAndCountsGiveThePooledDegreesOfFreedom) {
  // With s_A² = s_B² and n_A = n_B = n, ν = 2(n − 1) exactly.
  EXPECT_NEAR(welchTest(sampleMean(0, 3, 11), sampleMean(0.1, 3, 11)).df, 20.0, 1e-12);
}

TEST(Welch, PValuesMatchPrintedCriticalValues) {
  // Two-sided 5% critical values of Student's t: 2.228 (ν = 10), 2.086 (ν = 20); 1% at ν = 10:
  // 3.169. Build estimates whose ν is exactly 10 or 20 (n_A = n_B = 6 or 11, equal variances)
  // and whose t is the critical value.
  auto pAt = [](double t, double n) {
    const double v = 1.0;  // s² / n for each side
    return welchTest(sampleMean(0, v * n, n), sampleMean(t * std::sqrt(2 * v), v * n, n));
  };
  EXPECT_NEAR(pAt(2.228, 6).df, 10, 1e-12);
  EXPECT_NEAR(pAt(2.228, 6).p, 0.05, 2e-4);
  EXPECT_NEAR(pAt(3.169, 6).p, 0.01, 2e-5);
  EXPECT_NEAR(pAt(2.086, 11).p, 0.05, 2e-4);
  EXPECT_NEAR(pAt(-2.086, 11).p, 0.05, 2e-4);  // two-sided
}

TEST(Welch, ZeroVarianceInBothIsDecidedExactly) {
  const MeanEstimate a{0.25, 0, 0}, b{0.25, 0, 0}, c{0.2500001, 0, 0};
  EXPECT_TRUE(welchTest(a, b).deterministic);
  EXPECT_EQ(welchTest(a, b).p, 1.0);
  EXPECT_EQ(welchTest(a, c).p, 0.0);
}

TEST(Welch, ZeroVarianceOnOneSideUsesTheOther) {
  // A exact, B a plain sample: ν = n_B − 1.
  const WelchResult r = welchTest({1.0, 0, 0}, sampleMean(1.1, 0.5, 8));
  EXPECT_NEAR(r.df, 7, 1e-12);
  EXPECT_GT(r.p, 0);
  EXPECT_LT(r.p, 1);
}

TEST(Welch, RejectsInvalidEstimates) {
  EXPECT_THROW(welchTest({0, -1, 0}, {0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(welchTest({std::nan(""), 1, 1}, {0, 1, 1}), std::invalid_argument);
  EXPECT_THROW(sampleMean(0, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace verity::validation
