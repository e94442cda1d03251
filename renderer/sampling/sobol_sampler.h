// Owen-scrambled Sobol points, padded (Burley 2020, "Practical Hash-based Owen Scrambling";
// the padding of Ahmed and Wonka 2020, "Screen-space blue-noise diffusion of Monte Carlo
// sampling error via hierarchical ordering of pixels", as pbrt-v4's padded Sobol sampler).
//
// How dimensions are allotted along a path: every request is one padded dimension. The k-th
// call of a pixel sample (counting next1D() and next2D() calls alike) draws from its own
// point set:
// - next2D(): the 2D Sobol (0, 2)-sequence (sobol_points.h), its index shuffled and each
//   coordinate Owen-scrambled with seeds hashed from (seed, pixel, k);
// - next1D(): the van der Corput sequence, shuffled and scrambled the same way.
// So the pass renderer's first call (the position in the pixel) and second (the lens) are
// calls 0 and 1, then the integrator's requests follow in the order it makes them. Each call
// keeps the net property over a pixel's samples: the first 2^m samples of a pixel, in every
// 2D call, hold one point in each elementary interval of area 2^-m. Calls are independent of
// each other and of other pixels, so no pair of calls or pixels is correlated.
#pragma once

#include "sampling/sampler.h"
#include "sampling/sampler_type.h"

namespace verity {

class SobolSampler : public Sampler {
 public:
  void startPixelSample(const Point2i& pixel, int index) override;
  float next1D() override;
  Point2f next2D() override;
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<SobolSampler>(*this); }

 private:
  // hashValues(seed, pixel, k) of the k-th call, folded one value at a time, so the pixel's
  // part is hashed once per pixel sample.
  uint64_t callHash();
  // j, the call's shuffled sample index, from its hash h (sobol_sampler.cpp).
  uint32_t shuffledIndex(uint64_t h) const;
  // x, the call's scrambled dimension 0 of Sobol point j.
  static float scrambledDimension0(uint32_t j, uint64_t h);

  uint64_t pixelHash_ = 0;
  uint32_t mirroredIndex_ = 0;  // the sample index with its bits reversed
  int call_ = 0;                // the padded dimension of the next request
};

// "sobol" in the scene format (sampler_registry.h).
SamplerType sobolSamplerType();

}  // namespace verity
