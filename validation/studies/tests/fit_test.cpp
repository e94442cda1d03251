// The least-squares fit against numbers worked out by hand.
#include "validation/studies/fit.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(StudyFit, LogLogSkipsNonPositiveValues) {
  const LineFit f = fitLogLog({1, 2, 4, 8, 0}, {1, 0.5, 0.25, 0.125, 3});
  EXPECT_EQ(f.n, 4);
  EXPECT_NEAR(f.slope, -1, 1e-12);
}

TEST(StudyFit, MedianOfEvenAndOddCounts) {
  EXPECT_EQ(median({3, 1, 2}), 2);
  EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
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
