// Uniformity of every sampler's values across pixels and sample indices, by Pearson's
// chi-square test: each dimension alone (16 bins), each pair of dimensions of one sample
// (8 x 8 bins), and each dimension at horizontally neighbouring pixels (8 x 8 bins), which a
// randomization shared between pixels fails. Requests 2D, 2D, 1D, 2D, 1D (8 dimensions);
// fixed seed. The family of all tests is held at level 1% by Sidak's correction: each test
// at 1 - 0.99^(1/T).
//
// One sample per pixel: the samples of one pixel are dependent by design (stratified, a net),
// which the chi-square test's independent draws would not model; pixels are independently
// randomized, so one sample from each of 48 x 48 pixels gives independent points. The pixel
// pair (2k, 2k + 1) of a row takes sample index k mod 64, so indices 0..63 are all visited
// (the time-budget case crosses its rounds of 16, 16 and 32) and a pair shares its index.
#include <gtest/gtest.h>

#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <memory>
#include <vector>

#include "sampling/halton_sampler.h"
#include "sampling/independent_sampler.h"
#include "sampling/sobol_sampler.h"
#include "sampling/stratified_sampler.h"

namespace verity::sampler_uniformity_test {
namespace {

constexpr int kWidth = 48, kHeight = 48, kSamples = 64, kDimensions = 8;
constexpr double kFamilyLevel = 0.01;

struct Case {
  const char* name;
  std::unique_ptr<Sampler> sampler;
  int spp;
};

std::vector<Case> cases() {
  std::vector<Case> all;
  all.push_back({"independent", std::make_unique<IndependentSampler>(), kSamples});
  all.push_back({"stratified", std::make_unique<StratifiedSampler>(), kSamples});
  all.push_back({"stratified, time budget", std::make_unique<StratifiedSampler>(), 1 << 24});
  all.push_back({"halton owen", std::make_unique<HaltonSampler>(DigitScramble::Owen), kSamples});
  all.push_back({"halton permute_digits",
                 std::make_unique<HaltonSampler>(DigitScramble::PermuteDigits), kSamples});
  all.push_back({"sobol", std::make_unique<SobolSampler>(), kSamples});
  return all;
}

// values[pixel][dimension]
using Values = std::vector<std::array<float, kDimensions>>;

Values draw(Sampler& sampler, int spp) {
  sampler.setSeed(20260101);
  sampler.setSamplesPerPixel(spp);
  Values values(kWidth * kHeight);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      sampler.startPixelSample(Point2i(x, y), ((y * kWidth + x) / 2) % kSamples);
      auto& v = values[y * kWidth + x];
      int d = 0;
      for (bool is2D : {true, true, false, true, false}) {
        if (is2D) {
          const Point2f u = sampler.next2D();
          v[d++] = u.x(), v[d++] = u.y();
        } else {
          v[d++] = sampler.next1D();
        }
      }
    }
  return values;
}

int bin(float u, int bins) {
  EXPECT_TRUE(u >= 0 && u < 1) << u;
  return std::min(int(u * bins), bins - 1);
}

// The chi-square upper-tail probability of `counts` against equal expected counts.
double pValue(const std::vector<int>& counts) {
  double total = 0;
  for (int c : counts) total += c;
  const double expected = total / counts.size();
  double statistic = 0;
  for (int c : counts) statistic += (c - expected) * (c - expected) / expected;
  const boost::math::chi_squared_distribution<double> chi2(double(counts.size() - 1));
  return boost::math::cdf(boost::math::complement(chi2, statistic));
}

TEST(SamplerUniformity, ChiSquareOverPixelsAndIndices) {
  const int pairs = kDimensions * (kDimensions - 1) / 2;
  const int tests = int(cases().size()) * (kDimensions + pairs + kDimensions);
  const double level = 1 - std::pow(1 - kFamilyLevel, 1.0 / tests);
  for (Case& c : cases()) {
    const Values values = draw(*c.sampler, c.spp);
    for (int d = 0; d < kDimensions; ++d) {
      std::vector<int> counts(16);
      for (const auto& v : values) ++counts[bin(v[d], 16)];
      EXPECT_GT(pValue(counts), level) << c.name << ", dimension " << d;
    }
    for (int d = 0; d < kDimensions; ++d)
      for (int e = d + 1; e < kDimensions; ++e) {
        std::vector<int> counts(64);
        for (const auto& v : values) ++counts[bin(v[d], 8) * 8 + bin(v[e], 8)];
        EXPECT_GT(pValue(counts), level) << c.name << ", dimensions " << d << " and " << e;
      }
    for (int d = 0; d < kDimensions; ++d) {
      std::vector<int> counts(64);
      for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x + 1 < kWidth; x += 2)
          ++counts[bin(values[y * kWidth + x][d], 8) * 8 + bin(values[y * kWidth + x + 1][d], 8)];
      EXPECT_GT(pValue(counts), level) << c.name << ", dimension " << d << " at neighbours";
    }
  }
}

}  // namespace
}  // namespace verity::sampler_uniformity_test
