// The tile estimator (tile_pooling.h) by hand: mean of pixel means, variance
// Σ s_i²/n_i / P², Satterthwaite denominator Σ (s_i²/(n_i P²))² / (n_i − 1), over the
// pixels a mask marks.
#include <gtest/gtest.h>
#include <verity/stats/tile_pooling.h>

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
  int pixels = 0;
  const MeanEstimate t = poolPixels(a, {0, 0, 2, 1}, 1, pixelsWithSamples(a, 2), &pixels);
  EXPECT_EQ(pixels, 2);
  EXPECT_DOUBLE_EQ(t.mean, 2.0);
  EXPECT_DOUBLE_EQ(t.variance, 0.7);
  EXPECT_NEAR(t.dfDenominator, 0.0625 / 3 + 0.2025 / 9, 1e-15);
}

TEST(TilePooling, OnePixelTileIsThePlainWelchTest) {
  const PixelStatistics a = image(1, 1, {1.5}, {2.0}, {12});
  const PixelStatistics b = image(1, 1, {1.9}, {3.0}, {7});
  int pixels = 0;
  const WelchResult pooled = welchTest(poolPixels(a, {0, 0, 1, 1}, 0, {1}, &pixels),
                                       poolPixels(b, {0, 0, 1, 1}, 0, {1}, &pixels));
  const WelchResult plain = welchTest(sampleMean(1.5, 2.0, 12), sampleMean(1.9, 3.0, 7));
  EXPECT_DOUBLE_EQ(pooled.t, plain.t);
  EXPECT_DOUBLE_EQ(pooled.df, plain.df);
  EXPECT_DOUBLE_EQ(pooled.p, plain.p);
}

TEST(TilePooling, OnlyMarkedPixelsEnter) {
  const PixelStatistics a = image(3, 1, {1, 2, 100}, {1, 1, 1}, {4, 1, 4});
  EXPECT_EQ(pixelsWithSamples(a, 2), (std::vector<char>{1, 0, 1}));
  int pixels = 0;
  const MeanEstimate t = poolPixels(a, {0, 0, 3, 1}, 0, {1, 0, 0}, &pixels);
  EXPECT_EQ(pixels, 1);
  EXPECT_DOUBLE_EQ(t.mean, 1.0);
  EXPECT_DOUBLE_EQ(t.variance, 0.25);
  poolPixels(a, {1, 0, 3, 1}, 0, {1, 0, 0}, &pixels);
  EXPECT_EQ(pixels, 0);
  // A marked pixel without a variance is refused, not pooled.
  EXPECT_THROW(poolPixels(a, {0, 0, 3, 1}, 0, {1, 1, 0}, &pixels), std::invalid_argument);
}

}  // namespace
}  // namespace verity::validation
