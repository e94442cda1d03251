#include "sampling/stratified_sampler.h"

#include "core/hash.h"
#include "sampling/independent_sampler.h"

namespace verity {

namespace {
// Largest divisor of n not above √n, so that n = nx · ny with strata as square as possible.
int stratumColumns(int n) {
  int nx = static_cast<int>(std::sqrt(static_cast<double>(n)));
  while (nx > 1 && n % nx != 0) --nx;
  return std::max(nx, 1);
}
}  // namespace

void StratifiedSampler::startPixelSample(const Point2i& pixel, int index) {
  pixelKey_ = (uint64_t(uint32_t(pixel.y())) << 32) | uint32_t(pixel.x());
  index_ = index;
  dimension_ = 0;
  rng_.seed(hashValues(seed_, pixelKey_, 17), hashValues(seed_, pixelKey_, index));
}

float StratifiedSampler::next1D() {
  const uint64_t key = hashValues(seed_, pixelKey_, dimension_++);
  const uint32_t stratum = permuteIndex(static_cast<uint32_t>(index_), spp_, key);
  const float x = (stratum + uniformFloat(rng_())) / static_cast<float>(spp_);
  return std::min(x, kOneMinusEpsilon);
}

Point2f StratifiedSampler::next2D() {
  const uint64_t key = hashValues(seed_, pixelKey_, dimension_);
  dimension_ += 2;
  const int nx = stratumColumns(spp_), ny = spp_ / nx;
  const uint32_t stratum = permuteIndex(static_cast<uint32_t>(index_), spp_, key);
  const float jx = uniformFloat(rng_()), jy = uniformFloat(rng_());
  const float x = (static_cast<float>(stratum % nx) + jx) / static_cast<float>(nx);
  const float y = (static_cast<float>(stratum / nx) + jy) / static_cast<float>(ny);
  return {std::min(x, kOneMinusEpsilon), std::min(y, kOneMinusEpsilon)};
}

}  // namespace verity
