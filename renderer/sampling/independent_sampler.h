// Independent uniform samples from a PCG32 stream per (seed, pixel, sample index).
#pragma once

#include <pcg_random.hpp>

#include "sampling/sampler.h"
#include "sampling/sampler_type.h"

namespace verity {

class IndependentSampler : public Sampler {
 public:
  void startPixelSample(const Point2i& pixel, int index) override;
  float next1D() override;
  Point2f next2D() override;
  std::unique_ptr<Sampler> clone() const override {
    return std::make_unique<IndependentSampler>(*this);
  }
  bool samplesAreIndependent() const override { return true; }

 private:
  pcg32 rng_;
};

// "independent" in the scene format (sampler_registry.h), the default.
SamplerType independentSamplerType();

// Uniform float in [0, 1) from 32 random bits.
inline float uniformFloat(uint32_t bits) {
  return std::min(static_cast<float>(bits >> 8) * 0x1p-24f, kOneMinusEpsilon);
}

}  // namespace verity
