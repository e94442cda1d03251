// One sample per stratum for the stratified sampler, for prime and composite counts and for
// the rounds a time budget uses. The strata are rebuilt here from their description in
// stratified_sampler.h: 1D, n intervals of 1/n; 2D, n cells of area 1/n in round(sqrt n)
// columns of floor or ceil(n / columns) cells, the taller columns first; rounds [0, 16),
// [16, 32), [32, 64), ... once the count exceeds 2^16.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "sampling/stratified_sampler.h"

namespace verity {
namespace {

// The 2D stratum of u among n, as (column, cell in column).
std::pair<int, int> stratumOf(const Point2f& u, int n) {
  const int columns = std::max(1, int(std::lround(std::sqrt(double(n)))));
  int before = 0;  // cells in the columns to the left
  for (int c = 0; c < columns; ++c) {
    const int height = n / columns + (c < n % columns ? 1 : 0);
    // Column c spans [before / n, (before + height) / n).
    if (double(u.x()) * n < before + height) {
      EXPECT_GE(double(u.x()) * n, before);
      return {c, int(double(u.y()) * height)};
    }
    before += height;
  }
  ADD_FAILURE() << "x = " << u.x() << " outside [0, 1)";
  return {-1, -1};
}

// Samples [first, first + n) of `spp` at one pixel: each of the requests 2D, 1D, 2D, 1D holds
// one sample per stratum of n.
void expectOnePerStratum(int spp, int first, int n, const Point2i& pixel) {
  StratifiedSampler sampler;
  sampler.setSeed(2024);
  sampler.setSamplesPerPixel(spp);
  std::set<std::pair<int, int>> cells[2];
  std::set<int> intervals[2];
  for (int i = first; i < first + n; ++i) {
    sampler.startPixelSample(pixel, i);
    for (int r = 0; r < 2; ++r) {
      const Point2f u = sampler.next2D();
      ASSERT_TRUE(u.x() >= 0 && u.x() < 1 && u.y() >= 0 && u.y() < 1);
      cells[r].insert(stratumOf(u, n));
      const float x = sampler.next1D();
      ASSERT_TRUE(x >= 0 && x < 1);
      intervals[r].insert(int(double(x) * n));
    }
  }
  for (int r = 0; r < 2; ++r) {
    EXPECT_EQ(cells[r].size(), size_t(n))
        << "2D request " << r << ", samples [" << first << ", " << first + n << ") of " << spp;
    EXPECT_EQ(intervals[r].size(), size_t(n))
        << "1D request " << r << ", samples [" << first << ", " << first + n << ") of " << spp;
  }
}

TEST(StratifiedStrata, OnePerStratumForPrimeAndCompositeCounts) {
  for (int n : {1, 2, 3, 4, 5, 7, 8, 12, 13, 16, 17, 31, 64, 97, 100, 101, 1000, 1009})
    expectOnePerStratum(n, 0, n, Point2i(3, 4));
}

TEST(StratifiedStrata, EachRoundOfATimeBudgetIsStratified) {
  const int spp = 1 << 24;  // what a time-limited render asks for
  expectOnePerStratum(spp, 0, 16, Point2i(1, 2));
  for (int first = 16; first <= 2048; first *= 2)
    expectOnePerStratum(spp, first, first, Point2i(1, 2));
  // A count just above the largest single round: the last round is cut at the count.
  const int count = StratifiedSampler::kLargestRound + 1001;
  expectOnePerStratum(count, StratifiedSampler::kLargestRound, 1001, Point2i(0, 5));
}

TEST(StratifiedStrata, CountsUpToTheLargestRoundAreOneRound) {
  EXPECT_EQ(StratifiedSampler::roundOf(4095, 4096).size, 4096);
  expectOnePerStratum(4096, 0, 4096, Point2i(9, 9));
}

}  // namespace
}  // namespace verity
