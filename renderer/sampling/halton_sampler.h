// Randomized Halton points, one sequence per pixel: dimension d of sample i of a pixel is the
// radical inverse of i in the d-th prime base (Halton 1960), its digits scrambled with
// permutations keyed by (seed, pixel, d). Each next1D() takes one dimension and each next2D()
// two, in the order the integrator asks for them.
//
// Why a sequence per pixel rather than one sequence spread over the image (as pbrt-v3 does):
// a pixel's n samples are then the first n Halton points, stratified in every dimension and
// pair of low dimensions whatever the image size, and the independent randomization of each
// pixel keeps pixels uncorrelated, so an image's error is noise rather than structure. What
// it gives up is stratification across neighbouring pixels.
//
// Dimensions beyond Boost's table of the first 10,000 primes take hashed uniform
// values, still a function of (seed, pixel, index, dimension).
#pragma once

#include "sampling/radical_inverse.h"
#include "sampling/sampler.h"
#include "sampling/sampler_type.h"

namespace verity {

class HaltonSampler : public Sampler {
 public:
  explicit HaltonSampler(DigitScramble scramble) : scramble_(scramble) {}
  void startPixelSample(const Point2i& pixel, int index) override;
  float next1D() override;
  Point2f next2D() override;
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<HaltonSampler>(*this); }
  DigitScramble scramble() const { return scramble_; }

 private:
  float sample(int dimension) const;

  DigitScramble scramble_;
  uint64_t pixelKey_ = 0;
  int index_ = 0;
  int dimension_ = 0;
};

// "halton" in the scene format (sampler_registry.h).
SamplerType haltonSamplerType();

}  // namespace verity
