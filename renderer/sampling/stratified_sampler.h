// Jittered stratification: in every dimension (and every pair of dimensions for 2D
// requests) the samples of one pixel fall one per stratum, with the strata visited in an
// independent random order per pixel and dimension so that dimensions stay uncorrelated.
//
// Any count n: 1D strata are n intervals of width 1/n; 2D strata are n cells of area 1/n in
// round(sqrt n) columns, each column holding floor or ceil of n / columns cells stacked
// (a square grid when n is a square; nothing dropped when n is prime).
//
// Rounds: up to kLargestRound samples per pixel are stratified as one set. Larger counts (a
// time budget asks for 2^24 and stops early) are stratified in rounds of doubling size,
// samples [0, 16), [16, 32), [32, 64), ..., so that every completed round is stratified on its
// own and the completed rounds always hold at least half of the samples taken.
#pragma once

#include <pcg_random.hpp>

#include "sampling/sampler.h"
#include "sampling/sampler_type.h"

namespace verity {

class StratifiedSampler : public Sampler {
 public:
  static constexpr int kLargestRound = 1 << 16;
  static constexpr int kFirstRound = 16;  // the first round's size when there are rounds

  void startPixelSample(const Point2i& pixel, int index) override;
  float next1D() override;
  Point2f next2D() override;
  std::unique_ptr<Sampler> clone() const override {
    return std::make_unique<StratifiedSampler>(*this);
  }

  // The round holding sample `index` of `spp`: its number, its first sample and its size.
  struct Round {
    int number = 0, first = 0, size = 1;
  };
  static Round roundOf(int index, int spp);

 private:
  pcg32 rng_;  // jitter inside the stratum
  uint64_t pixelKey_ = 0;
  Round round_;
  int index_ = 0;  // within the round
  int dimension_ = 0;
};

// Cell s of the n equal-area 2D strata above, at the point `jitter` of the unit square.
Point2f stratumPoint(uint32_t s, uint32_t n, double jitterX, double jitterY);

// "stratified" in the scene format (sampler_registry.h).
SamplerType stratifiedSamplerType();

}  // namespace verity
