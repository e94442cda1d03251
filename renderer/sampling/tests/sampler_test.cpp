#include <gtest/gtest.h>

#include <set>

#include "core/hash.h"
#include "sampling/distribution.h"
#include "sampling/independent_sampler.h"
#include "sampling/stratified_sampler.h"

namespace verity {
namespace {

TEST(PermuteIndex, IsAPermutation) {
  for (uint32_t n : {1u, 2u, 5u, 16u, 17u, 1000u}) {
    std::set<uint32_t> seen;
    for (uint32_t i = 0; i < n; ++i) seen.insert(permuteIndex(i, n, 1234));
    EXPECT_EQ(seen.size(), n);
    EXPECT_LT(*seen.rbegin(), n);
  }
}

TEST(StratifiedSampler, OneSamplePerStratumInEveryDimension) {
  StratifiedSampler sampler;
  const int spp = 12;  // 3 × 4 strata in 2D
  sampler.setSamplesPerPixel(spp);
  sampler.setSeed(5);
  std::set<int> strata1D[3], strata2D[2];
  for (int i = 0; i < spp; ++i) {
    sampler.startPixelSample(Point2i(3, 4), i);
    for (int d = 0; d < 2; ++d) {
      const Point2f u = sampler.next2D();
      strata2D[d].insert(static_cast<int>(u.x() * 3) + 3 * static_cast<int>(u.y() * 4));
    }
    for (int d = 0; d < 3; ++d) strata1D[d].insert(static_cast<int>(sampler.next1D() * spp));
  }
  for (const auto& s : strata2D) EXPECT_EQ(s.size(), size_t(spp));
  for (const auto& s : strata1D) EXPECT_EQ(s.size(), size_t(spp));
}

TEST(Samplers, DependOnlyOnSeedPixelAndIndex) {
  IndependentSampler a, b;
  a.setSeed(9);
  b.setSeed(9);
  a.startPixelSample(Point2i(1, 2), 3);
  const float first = a.next1D();
  b.startPixelSample(Point2i(7, 7), 0);  // another pixel in between
  b.next1D();
  b.startPixelSample(Point2i(1, 2), 3);
  EXPECT_EQ(b.next1D(), first);
  a.startPixelSample(Point2i(1, 2), 4);
  EXPECT_NE(a.next1D(), first);
}

TEST(Distribution1D, SamplesInProportionAndSkipsZeros) {
  const Distribution1D d({1.0, 0.0, 3.0});
  EXPECT_FLOAT_EQ(d.pmf(0), 0.25f);
  EXPECT_FLOAT_EQ(d.pmf(1), 0.0f);
  EXPECT_EQ(d.sampleDiscrete(0.1f), 0u);
  EXPECT_EQ(d.sampleDiscrete(0.25f), 2u);  // the boundary never selects the empty bin
  EXPECT_EQ(d.sampleDiscrete(0.99f), 2u);
  float remapped = 0;
  d.sampleDiscrete(0.625f, nullptr, &remapped);
  EXPECT_NEAR(remapped, 0.5f, 1e-6f);
}

TEST(Distribution2D, PdfMatchesSamples) {
  const Distribution2D d({1, 2, 3, 4, 0, 6}, 3, 2);  // rows of 3
  for (float ux : {0.1f, 0.5f, 0.9f})
    for (float uy : {0.2f, 0.7f}) {
      float pdf = 0;
      const Point2f p = d.sample(Point2f(ux, uy), &pdf);
      EXPECT_NEAR(pdf, d.pdf(p), 1e-5f);
      EXPECT_GT(pdf, 0);
    }
  // Density of cell (1, 1) (weight 0) is zero; of cell (2, 1), 6 / 16 × 6 cells.
  EXPECT_EQ(d.pdf(Point2f(0.5f, 0.75f)), 0.0f);
  EXPECT_NEAR(d.pdf(Point2f(0.9f, 0.75f)), 6.0f / 16 * 6, 1e-5f);
}

}  // namespace
}  // namespace verity
