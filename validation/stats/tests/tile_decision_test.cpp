// The family decision on plain tile estimates (tile_decision.h): the z-score against printed
// normal quantiles, Holm at the family-wise level, and each test's detectable bias against
// the rejection rate measured by simulation at that bias.
#include <gtest/gtest.h>
#include <verity/stats/tile_decision.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <random>

namespace verity::validation {
namespace {

TileTest tileTest(int tile, int channel, MeanEstimate a, MeanEstimate b) {
  TileTest t;
  t.tileX = tile;
  t.channel = channel;
  t.pooled = {a, b, 1, 0};
  return t;
}

TEST(TileDecision, ZScoreIsTheNormalDeviateOfTheTwoSidedP) {
  // ν = 10 (n = 6 per side, equal variances) and t = 2.228, Student's printed two-sided 5%
  // point: the normal deviate of p = 0.05 is 1.95996 (printed), signed like B − A.
  const double n = 6, v = 1.0;
  std::vector<TileTest> tests = {
      tileTest(0, 0, sampleMean(0, v * n, n), sampleMean(2.228 * std::sqrt(2 * v), v * n, n)),
      tileTest(1, 0, sampleMean(2.228 * std::sqrt(2 * v), v * n, n), sampleMean(0, v * n, n)),
      tileTest(2, 0, {0.5, 0, 0}, {0.6, 0, 0}), tileTest(3, 0, {0.5, 0, 0}, {0.5, 0, 0})};
  decideTiles(tests, 0.01, 0.9);
  EXPECT_NEAR(tests[0].welch.p, 0.05, 2e-4);
  EXPECT_NEAR(tests[0].z, 1.95996, 2e-3);
  EXPECT_NEAR(tests[1].z, -1.95996, 2e-3);
  EXPECT_EQ(tests[2].z, std::numeric_limits<double>::infinity());  // deterministic, differ
  EXPECT_EQ(tests[3].z, 0.0);
  EXPECT_EQ(tests[2].detectableBias, 0.0);  // any difference of a noiseless tile is found
}

TEST(TileDecision, HolmDecidesTheFamilyAtItsLevel) {
  // Four noisy tests with p of about 1e-6, 0.03, 0.5, 0.9 at α = 1%: Holm's first step
  // compares 1e-6 with 0.01/4 (reject), the second 0.03 with 0.01/3 (stop).
  const auto at = [](double t) {
    return std::pair(sampleMean(0, 1e6, 1e6), sampleMean(t * std::sqrt(2.0), 1e6, 1e6));
  };
  std::vector<TileTest> tests;
  for (double t : {4.89, 2.17, 0.674, 0.126})
    tests.push_back(tileTest(0, 0, at(t).first, at(t).second));
  const TileDecision d = decideTiles(tests, 0.01, 0.9);
  EXPECT_NEAR(tests[1].welch.p, 0.03, 1e-3);
  EXPECT_TRUE(tests[0].rejected);
  EXPECT_FALSE(tests[1].rejected);
  EXPECT_EQ(d.holm.rejections, 1);
  EXPECT_TRUE(d.differ);
  EXPECT_EQ(d.deterministicTests, 0);
}

TEST(TileDecision, EachTestDetectsItsDetectableBiasWithTheStatedPower) {
  // m = 30 equal tests of N = 64 renders per side (values normal, σ = 0.1, mean 1) at
  // α = 1%, power 90%: a bias of the computed r* in B's expectation must be rejected at the
  // Bonferroni level α/m in 90% of 4000 simulated tests, within the binomial 99.9% interval.
  const int m = 30, renders = 64, trials = 4000;
  const double sigma = 0.1, alpha = 0.01, power = 0.9;
  std::vector<TileTest> tests;
  for (int i = 0; i < m; ++i)
    tests.push_back(tileTest(i, 0, sampleMean(1, sigma * sigma, renders),
                             sampleMean(1, sigma * sigma, renders)));
  decideTiles(tests, alpha, power);
  const double bias = tests[0].detectableBias;
  ASSERT_GT(bias, 0.0);
  ASSERT_LT(bias, 1.0);
  std::mt19937_64 rng(25);
  std::normal_distribution<double> normal;
  std::chi_squared_distribution<double> chi2(renders - 1);
  // A sample of `renders` normal values with mean mu, drawn through its sufficient statistics.
  const auto sample = [&](double mu) {
    return sampleMean(mu + sigma / std::sqrt(double(renders)) * normal(rng),
                      sigma * sigma * chi2(rng) / (renders - 1), renders);
  };
  int rejected = 0;
  for (int i = 0; i < trials; ++i)
    rejected += welchTest(sample(1.0), sample(1.0 + bias)).p <= alpha / m;
  const boost::math::binomial b(trials, power);
  EXPECT_GE(rejected, boost::math::quantile(b, 0.0005)) << "bias " << bias;
  EXPECT_LE(rejected, boost::math::quantile(boost::math::complement(b, 0.0005))) << "bias " << bias;
  std::printf("detectable bias %.4f: rejected %d of %d at alpha/m (power %.2f)\n", bias, rejected,
              trials, power);
}

}  // namespace
}  // namespace verity::validation
