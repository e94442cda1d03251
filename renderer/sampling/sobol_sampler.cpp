#include "sampling/sobol_sampler.h"

#include "core/hash.h"
#include "sampling/independent_sampler.h"
#include "sampling/sobol_points.h"

namespace verity {

void SobolSampler::startPixelSample(const Point2i& pixel, int index) {
  const uint64_t pixelKey = (uint64_t(uint32_t(pixel.y())) << 32) | uint32_t(pixel.x());
  pixelHash_ = hashValues(seed_, pixelKey);
  index_ = static_cast<uint32_t>(index);
  call_ = 0;
}

uint64_t SobolSampler::callHash() {
  return hashCombine(pixelHash_, static_cast<uint64_t>(call_++));
}

float SobolSampler::next1D() {
  const uint64_t h = callHash();
  // Shuffling by a nested scramble keeps the first 2^m indices an aligned block of 2^m.
  const uint32_t index = nestedUniformScramble(index_, static_cast<uint32_t>(h));
  return uniformFloat(nestedUniformScramble(sobolSample(index, 0), static_cast<uint32_t>(h >> 32)));
}

Point2f SobolSampler::next2D() {
  const uint64_t h = callHash();
  const uint32_t yScramble = static_cast<uint32_t>(mix64(h));
  const uint32_t index = nestedUniformScramble(index_, static_cast<uint32_t>(h));
  return {
      uniformFloat(nestedUniformScramble(sobolSample(index, 0), static_cast<uint32_t>(h >> 32))),
      uniformFloat(nestedUniformScramble(sobolSample(index, 1), yScramble))};
}

SamplerType sobolSamplerType() {
  return {
      "sobol",
      {},
      "Owen-scrambled Sobol points, padded: each 1D or 2D request its own set",
      {},  // no keys of its own
      [](const JsonNode*) -> std::unique_ptr<Sampler> { return std::make_unique<SobolSampler>(); }};
}

}  // namespace verity
