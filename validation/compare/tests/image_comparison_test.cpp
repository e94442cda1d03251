// The whole comparison on synthetic images from known distributions (fixed seeds): its size
// under the null, the uniformity of its p-values, its power against a 1% brightness bias
// (against the power it predicts), and its edge cases.
#include "validation/compare/image_comparison.h"

#include <gtest/gtest.h>
#include <verity/stats/power.h>

#include <boost/math/distributions/binomial.hpp>
#include <filesystem>

#include "core/error.h"
#include "synthetic_images.h"
#include "testing/error_of.h"
#include "validation/compare/comparison_report.h"
#include "validation/compare/exr_statistics.h"

namespace verity::validation {
namespace {

using testing::exponentialImage;
using testing::normalImage;

TEST(ImageComparison, IdenticalDistributionsAgree) {
  const ComparisonResult r = compareImages(exponentialImage(64, 48, 32, 1.0, 1, "a.exr"),
                                           exponentialImage(64, 48, 32, 1.0, 2, "b.exr"));
  EXPECT_EQ(r.tilesTested, 12);
  EXPECT_EQ(r.tests.size(), 36u);
  EXPECT_EQ(r.deterministicTests, 0);
  EXPECT_FALSE(r.differ) << comparisonSummary(r);
}

TEST(ImageComparison, FalseDifferenceRateIsAtMostAlphaAndPValuesAreUniform) {
  // 300 independent pairs from one distribution (skewed samples, fully correlated
  // channels): the number reported "differ" must not exceed the 99.9% binomial quantile of
  // 300 trials at α = 1% (Holm's guarantee), and each channel's p-values over all trials
  // (tiles and trials independent) must pass KS for U(0, 1) at 1%.
  const int trials = 300;
  int differ = 0;
  std::array<std::vector<double>, kChannels> pValues;
  for (int t = 0; t < trials; ++t) {
    const ComparisonResult r = compareImages(exponentialImage(64, 64, 8, 1.0, 1000 + 2 * t),
                                             exponentialImage(64, 64, 8, 1.0, 1001 + 2 * t));
    differ += r.differ;
    for (const TileTest& test : r.tests) pValues[test.channel].push_back(test.welch.p);
  }
  const boost::math::binomial b(trials, 0.01);
  EXPECT_LE(differ, boost::math::quantile(boost::math::complement(b, 0.001)));
  for (int c = 0; c < kChannels; ++c) {
    const KsResult ks = ksTestUniform(pValues[c]);
    EXPECT_EQ(ks.n, trials * 16);
    EXPECT_GT(ks.pValue, 0.01) << kChannelNames[c] << ": D = " << ks.statistic;
  }
}

TEST(ImageComparison, OnePercentBrightnessBiasIsDetected) {
  // 4,096 samples per pixel of relative standard deviation 1 in 16×16 tiles: a tile mean's
  // relative standard error is 1/√(256·4096) per image, so a 1% bias is 7.2 standard errors
  // of the difference, against a Bonferroni threshold of 3.3 for 12 tests.
  const PixelStatistics a = exponentialImage(32, 32, 4096, 1.0, 11);
  const PixelStatistics b = exponentialImage(32, 32, 4096, 1.01, 12);
  const ComparisonResult r = compareImages(a, b);
  EXPECT_TRUE(r.differ) << comparisonSummary(r);
  EXPECT_LT(r.detectableBias, 0.01);
  for (const TileTest& t : r.tests) EXPECT_GT(t.relativeDifference, 0);
}

TEST(ImageComparison, PowerAgainstABiasMatchesItsPrediction) {
  // A bias near the edge of detection: the fraction of 400 trials reported "differ" must lie
  // within the 0.1% binomial bounds around the mean predicted power (power.h). Fully
  // correlated channels make the lower bound of power.h its exact value up to the normal
  // approximation.
  std::mt19937_64 rng(99);
  const int trials = 400;
  const double bias = 0.01;
  int differ = 0;
  double predicted = 0;
  for (int t = 0; t < trials; ++t) {
    const PixelStatistics a = normalImage(32, 32, 400, 1.0, 1.0, rng);
    const PixelStatistics b = normalImage(32, 32, 400, 1.0, 1.0 + bias, rng);
    const ComparisonResult r = compareImages(a, b);
    differ += r.differ;
    std::vector<PowerTerm> terms;
    for (const TileTest& test : r.tests)
      terms.push_back({0.5 * (test.pooled.a.mean + test.pooled.b.mean),
                       test.pooled.a.variance + test.pooled.b.variance, test.welch.df,
                       test.channel});
    predicted += rejectionProbability(terms, int(r.tests.size()), 0.01, bias);
  }
  predicted /= trials;
  ASSERT_GT(predicted, 0.2);
  ASSERT_LT(predicted, 0.8);
  const boost::math::binomial b(trials, predicted);
  EXPECT_GE(differ, boost::math::quantile(b, 0.0005)) << "predicted " << predicted;
  EXPECT_LE(differ, boost::math::quantile(boost::math::complement(b, 0.0005)))
      << "predicted " << predicted;
  std::printf(
      "power against a 1%% bias, 32x32 px, 400 spp, sigma/mu = 1: measured %.3f "
      "(%d of %d), predicted %.3f\n",
      double(differ) / trials, differ, trials, predicted);
}

TEST(ImageComparison, ZeroVarianceTilesAreDecidedExactly) {
  PixelStatistics a = exponentialImage(32, 16, 8, 1.0, 3), b = exponentialImage(32, 16, 8, 1.0, 4);
  // Left tile: constant 0.5 in both (a black-and-white background); the right stays noisy.
  for (auto* s : {&a, &b})
    for (int c = 0; c < 3; ++c)
      for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
          s->mean[c][s->index(x, y)] = 0.5;
          s->variance[c][s->index(x, y)] = 0;
        }
  ComparisonResult r = compareImages(a, b);
  EXPECT_EQ(r.deterministicTests, 3);
  EXPECT_EQ(r.tests[0].welch.p, 1.0);
  EXPECT_EQ(r.uniformity[0].n, 1);  // deterministic tests stay out of the KS test
  EXPECT_FALSE(r.differ);
  // The same constant tile differing in one pixel by one float step: p = 0, differ.
  b.mean[1][b.index(3, 5)] = std::nextafter(0.5f, 1.0f);
  r = compareImages(a, b);
  EXPECT_EQ(r.tests[1].welch.p, 0.0);
  EXPECT_TRUE(r.tests[1].rejected);
  EXPECT_TRUE(r.differ);
  EXPECT_EQ(r.holm.rejections, 1);
}

TEST(ImageComparison, TilesWithTooFewSamplesAreNotTested) {
  PixelStatistics a = exponentialImage(40, 16, 8, 1.0, 5), b = exponentialImage(40, 16, 8, 1.0, 6);
  // The last tile (pixels 32..39) has one sample per pixel in B; one pixel of the first
  // tile has none in A.
  for (int y = 0; y < 16; ++y)
    for (int x = 32; x < 40; ++x) b.samples[b.index(x, y)] = 1;
  a.samples[a.index(0, 0)] = 0;
  const ComparisonResult r = compareImages(a, b);
  EXPECT_EQ(r.tilesTested, 2);
  EXPECT_EQ(r.tilesUntested, 1);
  EXPECT_EQ(r.pixelsExcluded, 8 * 16 + 1);
  EXPECT_EQ(r.tests.size(), 6u);
  EXPECT_EQ(r.tests[0].pooled.pixels, 255);
  // Nothing testable at all is bad input.
  for (double& s : b.samples) s = 1;
  EXPECT_NE(errorOf([&] { compareImages(a, b); }).find("render with more samples"),
            std::string::npos);
}

TEST(ImageComparison, MismatchedResolutionsNameBothFiles) {
  const std::string message = errorOf([] {
    compareImages(exponentialImage(32, 32, 4, 1.0, 1, "left.exr"),
                  exponentialImage(32, 16, 4, 1.0, 2, "right.exr"));
  });
  EXPECT_NE(message.find("left.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("right.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("32x32"), std::string::npos) << message;
  EXPECT_NE(message.find("32x16"), std::string::npos) << message;
}

TEST(ImageComparison, MissingVarianceChannelsSayToRenderWithVariance) {
  Film film(Vector2i(4, 4));
  film.addSample(0, 0, Color3(1, 1, 1));
  const std::string message =
      errorOf([&] { pixelStatistics(filmChannels(film, false), "plain.exr"); });
  EXPECT_NE(message.find("plain.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("variance.R"), std::string::npos) << message;
  EXPECT_NE(message.find("--variance"), std::string::npos) << message;
  // The same through a file on disk.
  const auto path = std::filesystem::temp_directory_path() / "verity-validation-plain.exr";
  writeExr(path, filmChannels(film, false));
  EXPECT_NE(errorOf([&] { loadPixelStatistics(path); }).find("--variance"), std::string::npos);
  std::filesystem::remove(path);
  // A sample-count plane is needed too.
  ImageChannels noCount = filmChannels(film, true);
  noCount.planes.erase("samples");
  EXPECT_NE(errorOf([&] { pixelStatistics(noCount, "x.exr"); }).find("\"samples\""),
            std::string::npos);
}

TEST(ImageComparison, InvalidValuesAndOptionsAreReported) {
  Film film(Vector2i(2, 2));
  ImageChannels image = filmChannels(film, true);
  image.planes["variance.G"][3] = -1;
  EXPECT_NE(errorOf([&] { pixelStatistics(image, "neg.exr"); }).find("pixel (1, 1)"),
            std::string::npos);
  const PixelStatistics s = exponentialImage(16, 16, 4, 1.0, 1);
  EXPECT_NE(errorOf([&] { compareImages(s, s, {.tileSize = 0}); }).find("--tile"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { compareImages(s, s, {.alpha = 1.0}); }).find("--alpha"),
            std::string::npos);
}

TEST(ImageComparison, SummaryAndJsonCarryTheDecision) {
  const PixelStatistics a = exponentialImage(32, 32, 4096, 1.0, 11, "a.exr");
  const PixelStatistics b = exponentialImage(32, 32, 4096, 1.01, 12, "b.exr");
  const ComparisonResult r = compareImages(a, b, {.tileSize = 8});
  EXPECT_EQ(r.tilesTested, 16);
  const std::string summary = comparisonSummary(r, 3);
  EXPECT_NE(summary.find("verdict: DIFFER"), std::string::npos) << summary;
  EXPECT_NE(summary.find("tile ("), std::string::npos) << summary;
  const nlohmann::json j = comparisonJson(r);
  EXPECT_EQ(j["differ"], true);
  EXPECT_EQ(j["tile_tests"].size(), 48u);
  EXPECT_EQ(j["tile_size"], 8);
}

}  // namespace
}  // namespace verity::validation
