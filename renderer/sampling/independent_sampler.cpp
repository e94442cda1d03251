#include "sampling/independent_sampler.h"

#include "core/hash.h"

namespace verity {

void IndependentSampler::startPixelSample(const Point2i& pixel, int index) {
  const uint64_t pixelKey = (uint64_t(uint32_t(pixel.y())) << 32) | uint32_t(pixel.x());
  rng_.seed(hashValues(seed_, pixelKey), hashValues(seed_ ^ 0x5bd1e995u, pixelKey, index));
}

float IndependentSampler::next1D() {
  return uniformFloat(rng_());
}

Point2f IndependentSampler::next2D() {
  const float x = next1D();
  return {x, next1D()};
}

SamplerType independentSamplerType() {
  return {"independent",
          {},
          "a fresh uniform random number for every sample and dimension (the default)",
          {},  // no keys of its own
          [](const JsonNode*) -> std::unique_ptr<Sampler> {
            return std::make_unique<IndependentSampler>();
          }};
}

}  // namespace verity
