// The KS statistic by hand, the Kolmogorov distribution against its tabulated quantiles, and
// the test's behaviour on uniform and non-uniform draws (fixed seeds).
#include <gtest/gtest.h>
#include <verity/stats/kolmogorov_smirnov.h>

#include <boost/math/distributions/binomial.hpp>
#include <cmath>
#include <random>

namespace verity::validation {
namespace {

TEST(KolmogorovSmirnov, StatisticByHand) {
  // Sorted 0.1, 0.2, 0.9 (n = 3): i/n − u = 0.233, 0.467, 0.1; u − (i−1)/n = 0.1, −0.133,
  // 0.233. D = 0.4667.
  const KsResult r = ksTestUniform({0.9, 0.1, 0.2});
  EXPECT_EQ(r.n, 3);
  EXPECT_NEAR(r.statistic, 2.0 / 3 - 0.2, 1e-12);
}

TEST(KolmogorovSmirnov, AsymptoticDistributionMatchesTabulatedQuantiles) {
  // Upper quantiles of the Kolmogorov distribution (Smirnov 1948): 1.2239 (10%), 1.3581 (5%),
  // 1.6276 (1%), 1.9495 (0.1%); its median is 0.8276.
  EXPECT_NEAR(kolmogorovSurvival(1.2239), 0.10, 1e-4);
  EXPECT_NEAR(kolmogorovSurvival(1.3581), 0.05, 1e-4);
  EXPECT_NEAR(kolmogorovSurvival(1.6276), 0.01, 1e-5);
  EXPECT_NEAR(kolmogorovSurvival(1.9495), 0.001, 1e-5);
  EXPECT_NEAR(kolmogorovSurvival(0.8276), 0.50, 2e-4);
  // Both series agree where they switch (λ = 1.18).
  EXPECT_NEAR(kolmogorovSurvival(1.1799999), kolmogorovSurvival(1.18), 1e-6);
  EXPECT_EQ(kolmogorovSurvival(0), 1.0);
  EXPECT_LT(kolmogorovSurvival(5), 1e-20);
}

TEST(KolmogorovSmirnov, HasItsStatedSizeOnUniformDraws) {
  // 2,000 samples of 20 uniform values: the fraction with p ≤ 5% must be consistent with 5%
  // (two-sided binomial bounds at 0.1%), small n being where the Stephens correction matters.
  std::mt19937_64 rng(20240501);
  std::uniform_real_distribution<double> u;
  const int trials = 2000;
  int rejections = 0;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> v(20);
    for (double& x : v) x = u(rng);
    rejections += ksTestUniform(v).pValue <= 0.05;
  }
  const boost::math::binomial b(trials, 0.05);
  EXPECT_GE(rejections, boost::math::quantile(b, 0.0005));
  EXPECT_LE(rejections, boost::math::quantile(boost::math::complement(b, 0.0005)));
}

TEST(KolmogorovSmirnov, DetectsNonUniformValues) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u;
  std::vector<double> squared(500), uniform(500);
  for (double& x : squared) x = std::pow(u(rng), 1.3);  // Beta(1/1.3, 1): excess near 0
  for (double& x : uniform) x = u(rng);
  EXPECT_LT(ksTestUniform(squared).pValue, 1e-4);
  EXPECT_GT(ksTestUniform(uniform).pValue, 0.01);
}

TEST(KolmogorovSmirnov, EmptyAndInvalidInput) {
  EXPECT_EQ(ksTestUniform({}).pValue, 1.0);
  EXPECT_THROW(ksTestUniform({0.5, -0.1}), std::invalid_argument);
}

}  // namespace
}  // namespace verity::validation
