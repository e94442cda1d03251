// Radical inverses against digit reversal done apart from the code under test, and the
// stratification that scrambling must keep: the first b^m points of a base-b inverse hold
// one point per interval of length b^-m, and the first 2^a 3^c Halton points one per box
// of 2^-a by 3^-c, under either randomization.
#include "sampling/radical_inverse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/special_functions/prime.hpp>
#include <charconv>
#include <set>
#include <string>

#include "core/hash.h"
#include "sampling/halton_sampler.h"

namespace verity {
namespace {

// i's base-b digits, written out by the standard library (bases up to 36), mirrored.
DigitFraction reversedByText(uint64_t i, uint32_t base) {
  char text[80];
  const auto end = std::to_chars(text, text + sizeof text, i, int(base)).ptr;
  std::string digits(text, end);
  if (i == 0) return {0, 1};
  std::reverse(digits.begin(), digits.end());
  DigitFraction x;
  std::from_chars(digits.data(), digits.data() + digits.size(), x.numerator, int(base));
  for (size_t k = 0; k < digits.size(); ++k) x.denominator *= base;
  return x;
}

TEST(RadicalInverse, IsTheMirroredDigitsExactlyInEveryBase) {
  std::vector<uint64_t> indices;
  for (uint64_t i = 0; i < 3000; ++i) indices.push_back(i);
  for (uint64_t i : std::initializer_list<uint64_t>{65535, 65536, 1 << 24, (1 << 24) - 1,
                                                    4294967295u, 123456789})
    indices.push_back(i);
  for (unsigned d = 0; boost::math::prime(d) <= 36; ++d) {
    const uint32_t base = boost::math::prime(d);
    for (uint64_t i : indices) {
      const DigitFraction expected = reversedByText(i, base);
      const DigitFraction x = radicalInverse(i, base);
      ASSERT_EQ(x.numerator, expected.numerator) << "base " << base << ", index " << i;
      ASSERT_EQ(x.denominator, expected.denominator) << "base " << base << ", index " << i;
      // The float is the exact fraction rounded once (numerator and denominator < 2^53).
      ASSERT_EQ(unitFloat(x),
                std::min(float(double(expected.numerator) / double(expected.denominator)),
                         0x1.fffffep-1f));
    }
  }
}

TEST(RadicalInverse, LargeBasesMirrorEveryDigit) {
  for (unsigned d : {11u, 100u, 1000u, 9999u}) {
    const uint32_t base = boost::math::prime(d);
    for (uint64_t i : std::initializer_list<uint64_t>{
             0, 1, uint64_t(base) - 1, uint64_t(base),
             std::min<uint64_t>(uint64_t(base) * base + 7, 4294967295u), 4294967295u}) {
      // Digits by hand, least significant first, then read back most significant first.
      std::vector<uint64_t> digits;
      for (uint64_t r = i; r > 0; r /= base) digits.push_back(r % base);
      uint64_t numerator = 0, denominator = 1;
      for (uint64_t digit : digits) numerator = numerator * base + digit, denominator *= base;
      const DigitFraction x = radicalInverse(i, base);
      EXPECT_EQ(x.numerator, numerator) << base << " " << i;
      EXPECT_EQ(x.denominator, denominator) << base << " " << i;
    }
  }
}

// The interval of length b^-m that holds x.
uint64_t intervalOf(const DigitFraction& x, uint64_t bm) {
  // Both are powers of the base; a plain inverse carries only the index's digits.
  if (x.denominator < bm) return x.numerator * (bm / x.denominator);
  return x.numerator / (x.denominator / bm);
}

TEST(RadicalInverse, ScramblingKeepsOnePointPerInterval) {
  for (DigitScramble scramble :
       {DigitScramble::None, DigitScramble::PermuteDigits, DigitScramble::Owen})
    for (uint32_t base : {2u, 3u, 5u, 7u, 29u, 7919u})
      for (uint64_t key : {1ull, 77ull}) {
        uint64_t bm = 1;
        for (int m = 0; bm <= 20000; ++m, bm *= base) {
          std::set<uint64_t> seen;
          for (uint64_t i = 0; i < bm; ++i)
            seen.insert(intervalOf(radicalInverse(i, base, scramble, key), bm));
          EXPECT_EQ(seen.size(), bm)
              << "base " << base << ", m " << m << ", scramble " << int(scramble);
        }
      }
}

TEST(RadicalInverse, ScramblingKeepsHaltonBoxesIn2D) {
  for (DigitScramble scramble :
       {DigitScramble::None, DigitScramble::PermuteDigits, DigitScramble::Owen})
    for (int a = 0; a <= 5; ++a)
      for (int c = 0; c <= 4; ++c) {
        const uint64_t nx = 1ull << a, ny = uint64_t(std::pow(3, c));
        std::set<std::pair<uint64_t, uint64_t>> seen;
        for (uint64_t i = 0; i < nx * ny; ++i)
          seen.insert({intervalOf(radicalInverse(i, 2, scramble, 11), nx),
                       intervalOf(radicalInverse(i, 3, scramble, 12), ny)});
        EXPECT_EQ(seen.size(), nx * ny) << a << " " << c << " " << int(scramble);
      }
}

// The sampler's base-2 dimension, as floats: exact multiples of 2^-24, so the test is exact.
TEST(HaltonSampler, FirstDimensionOnePointPerInterval) {
  for (DigitScramble scramble : {DigitScramble::PermuteDigits, DigitScramble::Owen}) {
    HaltonSampler sampler(scramble);
    sampler.setSeed(31);
    for (int m = 0; m <= 12; ++m) {
      std::set<int> seen;
      for (int i = 0; i < (1 << m); ++i) {
        sampler.startPixelSample(Point2i(5, 9), i);
        const float x = sampler.next2D().x();
        ASSERT_GE(x, 0.0f);
        ASSERT_LT(x, 1.0f);
        seen.insert(int(std::ldexp(x, m)));
      }
      EXPECT_EQ(seen.size(), size_t(1) << m) << m;
    }
  }
}

}  // namespace
}  // namespace verity
