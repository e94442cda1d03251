// Jittered stratification: in every dimension (and every pair of dimensions for 2D
// requests) the samples of one pixel fall one per stratum, with the strata visited in an
// independent random order per pixel and dimension so that dimensions stay uncorrelated.
#pragma once

#include <pcg_random.hpp>

#include "sampling/sampler.h"

namespace verity {

class StratifiedSampler : public Sampler {
 public:
  void startPixelSample(const Point2i& pixel, int index) override;
  float next1D() override;
  Point2f next2D() override;
  std::unique_ptr<Sampler> clone() const override {
    return std::make_unique<StratifiedSampler>(*this);
  }

 private:
  pcg32 rng_;  // jitter inside the stratum
  uint64_t pixelKey_ = 0;
  int index_ = 0;
  int dimension_ = 0;
};

}  // namespace verity
