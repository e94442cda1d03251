// Region statistics by batch means (batch_regions.h), checked by hand: the region's value in
// a batch is the mean of its pixels' means, its variance the sample variance over batches.
#include "validation/compare/batch_regions.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace verity::validation {
namespace {

// A 2×1 film whose pixels hold one sample each, grey values a and b.
Film film(float a, float b) {
  Film f(Vector2i(2, 1));
  f.addSample(0, 0, Color3::Constant(a));
  f.addSample(1, 0, Color3::Constant(b));
  return f;
}

TEST(BatchRegions, MeanAndVarianceOfTheBatchMeans) {
  // Region 0 holds both pixels, region 1 none. Batch values: (1 + 3) / 2 = 2, (2 + 6) / 2 = 4,
  // (0 + 0) / 2 = 0: mean 2, sample variance ((0)² + 2² + (−2)²) / 2 = 4.
  BatchRegions regions({0, 0}, 2, "test");
  regions.addBatch(film(1, 3));
  regions.addBatch(film(2, 6));
  regions.addBatch(film(0, 0));
  const PixelStatistics s = regions.statistics();
  EXPECT_EQ(s.width, 2);
  EXPECT_EQ(s.height, 1);
  for (int c = 0; c < kChannels; ++c) {
    EXPECT_DOUBLE_EQ(s.mean[c][0], 2.0);
    EXPECT_DOUBLE_EQ(s.variance[c][0], 4.0);
  }
  EXPECT_EQ(s.samples[0], 3);
  EXPECT_EQ(s.samples[1], 0);  // no pixel: left untested by compareImages
}

TEST(BatchRegions, PixelsOutsideEveryRegionAreLeftOut) {
  BatchRegions regions({-1, 0}, 1, "test");
  regions.addBatch(film(100, 1));
  regions.addBatch(film(-100, 3));
  const PixelStatistics s = regions.statistics();
  EXPECT_DOUBLE_EQ(s.mean[0][0], 2.0);
  EXPECT_DOUBLE_EQ(s.variance[0][0], 2.0);
}

TEST(BatchRegions, RefusesTooFewBatchesAndOtherResolutions) {
  BatchRegions regions({0, 0}, 1, "test");
  regions.addBatch(film(1, 1));
  EXPECT_THROW(regions.statistics(), VerityError);
  EXPECT_THROW(regions.addBatch(Film(Vector2i(3, 1))), VerityError);
}

TEST(TileRegions, PartialTilesAtTheEdges) {
  int tiles = 0;
  const std::vector<int> r = tileRegions(3, 3, 2, &tiles);
  EXPECT_EQ(tiles, 4);
  EXPECT_EQ(r, (std::vector<int>{0, 0, 1, 0, 0, 1, 2, 2, 3}));
}

}  // namespace
}  // namespace verity::validation
