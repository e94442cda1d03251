// The least-squares fit against numbers worked out by hand.
#include "validation/studies/fit.h"

#include <gtest/gtest.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <random>

#include "validation/studies/seeds.h"

namespace verity::studies {
namespace {

TEST(StudyFit, ExactLineHasZeroWidthInterval) {
  const LineFit f = fitLine({0, 1, 2, 3}, {2, 1, 0, -1});
  EXPECT_EQ(f.n, 4);
  EXPECT_NEAR(f.slope, -1, 1e-12);
  EXPECT_NEAR(f.intercept, 2, 1e-12);
  EXPECT_NEAR(f.slopeLow, -1, 1e-9);
  EXPECT_NEAR(f.slopeHigh, -1, 1e-9);
}

TEST(StudyFit, IntervalMatchesHandComputation) {
  // x̄ = ȳ = 3, Sxx = 10, Sxy = 8: slope 0.8, intercept 0.6; residuals −0.4, 0.8, −1, 1.2,
  // −0.6: SSE 3.6, s² = 1.2, se = sqrt(0.12); t(0.975, 3 dof) = 3.182446305284263.
  const LineFit f = fitLine({1, 2, 3, 4, 5}, {1, 3, 2, 5, 4});
  EXPECT_NEAR(f.slope, 0.8, 1e-12);
  EXPECT_NEAR(f.intercept, 0.6, 1e-12);
  EXPECT_NEAR(f.slopeStdError, std::sqrt(0.12), 1e-12);
  const double half = 3.182446305284263 * std::sqrt(0.12);
  EXPECT_NEAR(f.slopeLow, 0.8 - half, 1e-9);
  EXPECT_NEAR(f.slopeHigh, 0.8 + half, 1e-9);
}

TEST(StudyFit, CrossingIsUnboundedWhenTheSlopeIsNotSignificant) {
  // The fit above: t·se = 1.10 exceeds the slope 0.8, so no bounded interval exists.
  const Crossing c = crossing(fitLine({1, 2, 3, 4, 5}, {1, 3, 2, 5, 4}), 3);
  EXPECT_NEAR(c.x, 3, 1e-12);  // (3 − 0.6) / 0.8
  EXPECT_FALSE(c.bounded);
}

TEST(StudyFit, CrossingIntervalEndsLieOnTheConfidenceBand) {
  const std::vector<double> x = {0, 1, 2, 3, 4, 5}, y = {10.1, 8.0, 6.2, 3.9, 2.1, -0.2};
  const LineFit f = fitLine(x, y);
  for (double target : {7.0, 2.5, -3.0}) {  // inside the data, and beyond it
    const Crossing c = crossing(f, target);
    ASSERT_TRUE(c.bounded);
    EXPECT_LT(c.low, c.x);
    EXPECT_GT(c.high, c.x);
    // At either end the band of the mean, ŷ ± t·s·√(1/n + (x − x̄)²/Sxx), just reaches target.
    for (double end : {c.low, c.high}) {
      const double halfWidth = f.tQuantile * f.residualStd *
                               std::sqrt(1.0 / f.n + (end - f.meanX) * (end - f.meanX) / f.sxx);
      EXPECT_NEAR(std::abs(target - (f.intercept + f.slope * end)), halfWidth, 1e-9);
    }
  }
}

// The interval's coverage of the true crossing, over simulated lines with Gaussian noise: a
// 95% interval must cover it in 95% of 4000 fits; the binomial count is accepted within its
// two-sided 0.1% acceptance region (one test, no correction; seed fixed).
TEST(StudyFit, CrossingIntervalCoversTheTrueCrossing) {
  std::mt19937_64 rng(20261124);
  std::normal_distribution<double> noise(0, 0.3);
  const std::vector<double> x = {0, 0.7, 1.4, 2.1, 2.8, 3.5};
  const double slope = -1, intercept = 1, target = -1.5;  // true crossing at 2.5
  const int trials = 4000;
  int covered = 0;
  for (int i = 0; i < trials; ++i) {
    std::vector<double> y;
    for (double xi : x) y.push_back(intercept + slope * xi + noise(rng));
    const Crossing c = crossing(fitLine(x, y), target);
    covered += c.bounded && c.low <= 2.5 && 2.5 <= c.high;
  }
  const boost::math::binomial_distribution<double> expected(trials, 0.95);
  EXPECT_GE(covered, boost::math::quantile(expected, 0.0005));
  EXPECT_LE(covered, boost::math::quantile(boost::math::complement(expected, 0.0005)));
}

TEST(StudyFit, LogLogSkipsNonPositiveValues) {
  const LineFit f = fitLogLog({1, 2, 4, 8, 0}, {1, 0.5, 0.25, 0.125, 3});
  EXPECT_EQ(f.n, 4);
  EXPECT_NEAR(f.slope, -1, 1e-12);
}

TEST(StudyFit, MedianOfEvenAndOddCounts) {
  EXPECT_EQ(median({3, 1, 2}), 2);
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
  EXPECT_TRUE(std::isnan(median({})));
}

TEST(StudySeeds, DependOnEveryPartOfTheKey) {
  const uint64_t s = runSeed("path_tracer_nee", "spp", 16, 0);
  EXPECT_EQ(s, runSeed("path_tracer_nee", "spp", 16, 0));
  EXPECT_NE(s, runSeed("path_tracer_mis", "spp", 16, 0));
  EXPECT_NE(s, runSeed("path_tracer_nee", "time", 16, 0));
  EXPECT_NE(s, runSeed("path_tracer_nee", "spp", 32, 0));
  EXPECT_NE(s, runSeed("path_tracer_nee", "spp", 16, 1));
}

}  // namespace
}  // namespace verity::studies
