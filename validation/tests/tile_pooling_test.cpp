// The tile estimator (tile_pooling.h) by hand: mean of pixel means, variance
// Σ s_i²/n_i / P², Satterthwaite denominator Σ (s_i²/(n_i P²))² / (n_i − 1).
#include "validation/tile_pooling.h"

#include <gtest/gtest.h>

namespace verity::validation {
namespace {

PixelStatistics image(int w, int h, std::vector<double> mean, std::vector<double> variance,
                      std::vector<double> samples) {
  PixelStatistics s;
  s.width = w;
  s.height = h;
  for (int c = 0; c < 3; ++c) {
    s.mean[c] = mean;
    s.variance[c] = variance;
  }
  s.samples = std::move(samples);
  return s;
}

TEST(TilePooling, MeanOfPixelMeansAndItsVariance) {
  // Two pixels: (m, s², n) = (1, 4, 4) and (3, 18, 10).
  // M = 2; V = (4/4 + 18/10) / 4 = 0.7; denominator = ((1/4)²/3 + (0.45)²/9) = 0.0433333.
  const PixelStatistics a = image(2, 1, {1, 3}, {4, 18}, {4, 10});
  const PooledTile t = poolTile(a, a, {0, 0, 2, 1}, 1, 2);
  EXPECT_EQ(t.pixels, 2);
  EXPECT_EQ(t.excluded, 0);
  EXPECT_DOUBLE_EQ(t.a.mean, 2.0);
  EXPECT_DOUBLE_EQ(t.a.variance, 0.7);
  EXPECT_NEAR(t.a.dfDenominator, 0.0625 / 3 + 0.2025 / 9, 1e-15);
}

TEST(TilePooling, OnePixelTileIsThePlainWelchTest) {
  const PixelStatistics a = image(1, 1, {1.5}, {2.0}, {12});
  const PixelStatistics b = image(1, 1, {1.9}, {3.0}, {7});
  const PooledTile t = poolTile(a, b, {0, 0, 1, 1}, 0, 2);
  const WelchResult pooled = welchTest(t.a, t.b);
  const WelchResult plain = welchTest(sampleMean(1.5, 2.0, 12), sampleMean(1.9, 3.0, 7));
  EXPECT_DOUBLE_EQ(pooled.t, plain.t);
  EXPECT_DOUBLE_EQ(pooled.df, plain.df);
  EXPECT_DOUBLE_EQ(pooled.p, plain.p);
}

TEST(TilePooling, PixelsWithTooFewSamplesInEitherImageAreLeftOutOfBoth) {
  const PixelStatistics a = image(3, 1, {1, 2, 100}, {1, 1, 1}, {4, 1, 4});
  const PixelStatistics b = image(3, 1, {1, 2, 5}, {1, 1, 1}, {4, 4, 0});
  const PooledTile t = poolTile(a, b, {0, 0, 3, 1}, 0, 2);
  EXPECT_EQ(t.pixels, 1);
  EXPECT_EQ(t.excluded, 2);
  EXPECT_DOUBLE_EQ(t.a.mean, 1.0);
  EXPECT_DOUBLE_EQ(t.b.mean, 1.0);
  EXPECT_EQ(poolTile(a, b, {1, 0, 3, 1}, 0, 2).pixels, 0);
}

}  // namespace
}  // namespace verity::validation
