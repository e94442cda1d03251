// The net property of the padded Sobol points: the first 2^m points of the 2D Sobol sequence,
// plain and Owen-scrambled with a shuffled index, and of every 2D request of the sampler, hold
// exactly one point in each elementary interval [a 2^-k, (a+1) 2^-k) x [c 2^-(m-k), (c+1)
// 2^-(m-k)), for every k; 1D requests hold one point per interval of length 2^-m.
#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "core/hash.h"
#include "sampling/independent_sampler.h"
#include "sampling/sobol_points.h"
#include "sampling/sobol_sampler.h"

namespace verity {
namespace {

struct Point32 {
  uint32_t x, y;  // fractions of 2^32
};

// Empty when the points form a (0, m, 2)-net, else the first interval shape that fails.
std::string netFailure(const std::vector<Point32>& points, int m) {
  if (points.size() != (size_t(1) << m)) return "wrong point count";
  for (int k = 0; k <= m; ++k) {
    std::vector<char> occupied(points.size());
    size_t twice = 0;
    for (const Point32& p : points) {
      const uint64_t a = k ? p.x >> (32 - k) : 0, c = m - k ? p.y >> (32 - (m - k)) : 0;
      twice += occupied[(a << (m - k)) | c]++ != 0;
    }
    if (twice)
      return "intervals 2^-" + std::to_string(k) + " x 2^-" + std::to_string(m - k) + ": " +
             std::to_string(twice) + " points in an occupied one";
  }
  return "";
}

uint32_t fraction32(float u) {
  EXPECT_GE(u, 0.0f);
  EXPECT_LT(u, 1.0f);
  return static_cast<uint32_t>(std::ldexp(double(u), 32));  // exact: u is a multiple of 2^-24
}

// Dimension 1 over the whole 32-bit index range, which a scrambled index reaches: its
// generator matrix is Pascal's triangle mod 2 (Sobol 1967), so index 2^k maps to the fraction
// whose bit i (i = 0 the 1/2 bit) is C(k, i) mod 2, which by Lucas' theorem is 1 exactly
// when the bits of i are a subset of those of k; and the map is linear over GF(2).
TEST(SobolPoints, DimensionOneIsPascalsTriangleForEveryIndexBit) {
  for (uint32_t k = 0; k < 32; ++k) {
    uint32_t expected = 0;
    for (uint32_t i = 0; i <= k; ++i)
      if ((i & k) == i) expected |= 0x80000000u >> i;
    EXPECT_EQ(sobolSample(1u << k, 1), expected) << "index 2^" << k;
  }
  uint64_t state = 12345;
  const auto next = [&] { return static_cast<uint32_t>((state = mix64(state + 1)) >> 16); };
  for (int n = 0; n < 10000; ++n) {
    const uint32_t a = next(), b = next();
    ASSERT_EQ(sobolSample(a ^ b, 1), sobolSample(a, 1) ^ sobolSample(b, 1)) << a << " " << b;
  }
  EXPECT_EQ(sobolSample(0, 1), 0u);
}

TEST(SobolPoints, FirstPointsFormNets) {
  for (int m = 0; m <= 16; ++m) {
    std::vector<Point32> points;
    for (uint32_t i = 0; i < (1u << m); ++i)
      points.push_back({sobolSample(i, 0), sobolSample(i, 1)});
    EXPECT_EQ(netFailure(points, m), "") << "m = " << m;
  }
}

TEST(SobolPoints, ShuffledAndScrambledPointsFormNets) {
  for (uint32_t seed : {1u, 0x9e3779b9u, 0xdeadbeefu})
    for (int m = 0; m <= 16; ++m) {
      std::vector<Point32> points;
      for (uint32_t i = 0; i < (1u << m); ++i) {
        const uint32_t index = nestedUniformScramble(i, seed);
        points.push_back({nestedUniformScramble(sobolSample(index, 0), seed * 3 + 1),
                          nestedUniformScramble(sobolSample(index, 1), seed * 5 + 2)});
      }
      EXPECT_EQ(netFailure(points, m), "") << "m = " << m << ", seed " << seed;
    }
}

TEST(SobolPoints, ScramblingChangesThePoints) {
  int moved = 0;
  for (uint32_t i = 0; i < 256; ++i)
    moved += nestedUniformScramble(sobolSample(i, 0), 7) != sobolSample(i, 0);
  EXPECT_GT(moved, 200);
}

TEST(SobolPoints, ReverseBitsMirrorsEachBit) {
  for (int i = 0; i < 32; ++i) EXPECT_EQ(reverseBits(1u << i), 0x80000000u >> i) << "bit " << i;
  uint64_t state = 7;
  for (int n = 0; n < 1000; ++n) {
    const uint32_t x = static_cast<uint32_t>(state = mix64(state + 1));
    ASSERT_EQ(reverseBits(reverseBits(x)), x);
    ASSERT_EQ(sobolDimension1Mirrored(x), reverseBits(sobolSample(x, 1))) << x;
  }
}

// The sampler computes its requests with fewer bit reversals than the plain composition of
// the scrambles (sobol_sampler.cpp); both must give the same bits.
TEST(SobolSampler, RequestsAreTheScrambledPointsOfTheirHashes) {
  constexpr uint64_t kSeed = 99;
  SobolSampler sampler;
  sampler.setSeed(kSeed);
  sampler.setSamplesPerPixel(1 << 20);
  for (const Point2i& pixel : {Point2i(0, 0), Point2i(5, 1234), Point2i(70000, 3)})
    for (uint32_t index : {0u, 1u, 6u, 255u, 65537u, 1000003u}) {
      sampler.startPixelSample(pixel, static_cast<int>(index));
      const uint64_t pixelKey = (uint64_t(uint32_t(pixel.y())) << 32) | uint32_t(pixel.x());
      for (int call = 0; call < 8; ++call) {
        const uint64_t h = hashValues(kSeed, pixelKey, call);
        const uint32_t j = nestedUniformScramble(index, static_cast<uint32_t>(h));
        const uint32_t x = nestedUniformScramble(sobolSample(j, 0), static_cast<uint32_t>(h >> 32));
        if (call % 3 == 1) {
          ASSERT_EQ(sampler.next1D(), uniformFloat(x)) << "call " << call;
        } else {
          const uint32_t y =
              nestedUniformScramble(sobolSample(j, 1), static_cast<uint32_t>(mix64(h)));
          const Point2f u = sampler.next2D();
          ASSERT_EQ(u.x(), uniformFloat(x)) << "call " << call;
          ASSERT_EQ(u.y(), uniformFloat(y)) << "call " << call;
        }
      }
    }
}

// Every request of the sampler, in the order a path makes them (2D, 2D, 1D, 2D, 1D, 2D).
TEST(SobolSampler, EveryRequestIsANetOverAPixelsSamples) {
  const bool is2D[] = {true, true, false, true, false, true};
  constexpr int kRequests = 6;
  for (const Point2i& pixel : {Point2i(0, 0), Point2i(17, 3)})
    for (int m = 0; m <= 12; ++m) {
      std::vector<Point32> points[kRequests];
      SobolSampler sampler;
      sampler.setSeed(12345);
      sampler.setSamplesPerPixel(1 << m);
      for (int i = 0; i < (1 << m); ++i) {
        sampler.startPixelSample(pixel, i);
        for (int r = 0; r < kRequests; ++r) {
          if (is2D[r]) {
            const Point2f u = sampler.next2D();
            points[r].push_back({fraction32(u.x()), fraction32(u.y())});
          } else {
            points[r].push_back({fraction32(sampler.next1D()), 0});
          }
        }
      }
      for (int r = 0; r < kRequests; ++r) {
        if (is2D[r]) {
          EXPECT_EQ(netFailure(points[r], m), "") << "request " << r << ", m = " << m;
        } else {
          std::set<uint32_t> intervals;
          for (const Point32& p : points[r]) intervals.insert(m ? p.x >> (32 - m) : 0);
          EXPECT_EQ(intervals.size(), size_t(1) << m) << "request " << r << ", m = " << m;
        }
      }
    }
}

}  // namespace
}  // namespace verity
