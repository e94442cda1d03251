// The power formulas against values derived without them: Cohen's tables of the noncentral
// χ² (Cohen 1988, Table 7.4.6), the closed form of one degree of freedom, and the normal
// approximation of the binomial far from 0 and 1.
#include <gtest/gtest.h>
#include <verity/chi2/power.h>

#include <cmath>
#include <stdexcept>

namespace verity::chi2 {
namespace {

TEST(Power, NoncentralityMatchesCohensTable) {
  // λ for a test at level 0.05 with power 0.80 and 0.90 (Cohen 1988, Table 7.4.6, two
  // decimals).
  EXPECT_NEAR(chiSquareNoncentrality(1, 0.05, 0.80), 7.85, 0.006);
  EXPECT_NEAR(chiSquareNoncentrality(1, 0.05, 0.90), 10.51, 0.006);
  EXPECT_NEAR(chiSquareNoncentrality(2, 0.05, 0.80), 9.64, 0.006);
  EXPECT_NEAR(chiSquareNoncentrality(2, 0.05, 0.90), 12.65, 0.006);
  EXPECT_NEAR(chiSquareNoncentrality(4, 0.05, 0.80), 11.94, 0.006);
  EXPECT_NEAR(chiSquareNoncentrality(4, 0.05, 0.90), 15.41, 0.006);
}

TEST(Power, OneDegreeOfFreedomMatchesTheNormalClosedForm) {
  // With one dof the statistic is (Z + √λ)², so power = Φ(√λ − z) + Φ(−√λ − z), z = √critical.
  // At level 0.001, z = 3.2905267; power 0.9 puts √λ − z at the 90% quantile 1.2815516 (the
  // far tail adds below 10⁻¹⁰).
  const double sqrtLambda = 3.2905267 + 1.2815516;
  EXPECT_NEAR(chiSquareNoncentrality(1, 0.001, 0.9), sqrtLambda * sqrtLambda, 1e-4);
}

TEST(Power, EffectSizeIsTheDensityErrorFamilysOwn) {
  // Density 1 ± ε over two cell sets of mass m each: w² = m·ε² + m·ε².
  const double m = 0.25, eps = 0.02;
  EXPECT_NEAR(effectForDensityError(eps, m), std::sqrt(m * eps * eps + m * eps * eps), 1e-15);
  EXPECT_NEAR(densityErrorForEffect(effectForDensityError(eps, m), m), eps, 1e-15);
  const ChiSquarePower p = chiSquarePower(63, 1e6, 0.01, 0.9);
  EXPECT_NEAR(p.effectSize * p.effectSize * 1e6, chiSquareNoncentrality(63, 0.01, 0.9), 1e-9);
  EXPECT_NE(p.describe().find("over cells holding 1/4 of the mass"), std::string::npos)
      << p.describe();
  EXPECT_NE(p.describe().find("with 90% probability"), std::string::npos) << p.describe();
}

TEST(Power, TooFewSamplesClaimNothing) {
  // Ten samples over 63 dof cannot see any density error over a quarter of the mass.
  const ChiSquarePower p = chiSquarePower(63, 10, 0.01, 0.9);
  EXPECT_GT(p.densityError(kStatedMass), 1);
  EXPECT_NE(p.describe().find("no density error"), std::string::npos) << p.describe();
}

// A test that did not run (the default) caught nothing, and says so: it once stated "a 0%
// density error ... would have been found with 0% probability".
TEST(Power, ATestThatDidNotRunClaimsNothing) {
  const ChiSquarePower p;
  EXPECT_FALSE(p.ran());
  EXPECT_EQ(p.describe(), "nothing: the chi-square test did not run");
  EXPECT_TRUE(std::isinf(p.densityError(kStatedMass)));
  EXPECT_TRUE(chiSquarePower(63, 1e6, 0.01, 0.9).ran());
}

TEST(Power, IntegralPowerMatchesTheNormalApproximation) {
  // Half the samples valid, 10⁶ of them: the check fails a claim I when the valid fraction
  // falls (z_{1−α/2} + z_power)·σ below I − tol, σ = √(q(1 − q)/N) ≈ 5·10⁻⁴.
  const double tol = 1e-4, sigma = 0.5 / 1000;
  const double expected = tol + (2.5758293 + 1.2815516) * sigma;
  const IntegralPower p = integralPower(0.5, 1'000'000, 0.01, tol, 0.9);
  ASSERT_TRUE(p.tooHigh && p.tooLow);
  EXPECT_NEAR(*p.tooHigh, expected, 0.01 * expected);
  EXPECT_NEAR(*p.tooLow, expected, 0.01 * expected);
}

TEST(Power, AllValidSamplesBoundTheClaimFromOneSide) {
  // Every sample valid and ∫pdf = 1: only a sampler that succeeds less often than claimed is
  // a possible error. With a failure rate δ the failures are about Poisson(N·δ), and the check
  // sees them once δ − tol exceeds (z_{1−α/2} + z_power)·√(δ/N): δ solves that fixed point.
  const double tol = 1e-4, n = 1e6, z = 2.5758293 + 1.2815516;
  double expected = tol;
  for (int i = 0; i < 50; ++i) expected = tol + z * std::sqrt(expected / n);
  const IntegralPower p = integralPower(1.0, 1'000'000, 0.01, tol, 0.9);
  EXPECT_FALSE(p.tooLow);
  ASSERT_TRUE(p.tooHigh);
  EXPECT_NEAR(*p.tooHigh, expected, 0.03 * expected);
}

TEST(Power, OutOfRangeQuestionsAreRefused) {
  EXPECT_THROW(chiSquareNoncentrality(0, 0.01, 0.9), std::invalid_argument);
  EXPECT_THROW(chiSquareNoncentrality(3, 0.01, 1.0), std::invalid_argument);
  EXPECT_THROW(chiSquareNoncentrality(3, 0.5, 0.4), std::invalid_argument);
  EXPECT_THROW(validate(DetectionTarget{0, 0.25, 0.9}), std::invalid_argument);
  EXPECT_THROW(validate(DetectionTarget{0.01, 0.75, 0.9}), std::invalid_argument);
  EXPECT_THROW(validate(DetectionTarget{0.01, 0.25, 1.5}), std::invalid_argument);
  EXPECT_NO_THROW(validate(DetectionTarget{0.01, 0.25, 0.9}));
}

}  // namespace
}  // namespace verity::chi2
