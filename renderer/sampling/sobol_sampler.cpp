#include "sampling/sobol_sampler.h"

#include "core/hash.h"
#include "sampling/independent_sampler.h"
#include "sampling/sobol_points.h"

namespace verity {

void SobolSampler::startPixelSample(const Point2i& pixel, int index) {
  const uint64_t pixelKey = (uint64_t(uint32_t(pixel.y())) << 32) | uint32_t(pixel.x());
  pixelHash_ = hashValues(seed_, pixelKey);
  mirroredIndex_ = reverseBits(static_cast<uint32_t>(index));
  call_ = 0;
}

uint64_t SobolSampler::callHash() {
  return hashCombine(pixelHash_, static_cast<uint64_t>(call_++));
}

// Each request is, with scramble = nestedUniformScramble = R ∘ LK ∘ R (R: reverseBits, LK:
// laineKarrasPermutation) and seeds a, b, c from the call's hash,
//   j = scramble(index, a),
//   x = scramble(sobolSample(j, 0), b),  y = scramble(sobolSample(j, 1), c).
// Since sobolSample(j, 0) = R(j) and R ∘ R is the identity, j = R(LK(R(index), a)) and
// x = R(LK(j, b)), and y = R(LK(R(sobolSample(j, 1)), c)) reads the mirrored table: the same
// bits with three reversals instead of seven.
uint32_t SobolSampler::shuffledIndex(uint64_t h) const {
  return reverseBits(laineKarrasPermutation(mirroredIndex_, static_cast<uint32_t>(h)));
}

float SobolSampler::scrambledDimension0(uint32_t j, uint64_t h) {
  return uniformFloat(reverseBits(laineKarrasPermutation(j, static_cast<uint32_t>(h >> 32))));
}

float SobolSampler::next1D() {
  const uint64_t h = callHash();
  return scrambledDimension0(shuffledIndex(h), h);
}

Point2f SobolSampler::next2D() {
  const uint64_t h = callHash();
  const uint32_t j = shuffledIndex(h);
  const uint32_t yScramble = static_cast<uint32_t>(mix64(h));
  return {scrambledDimension0(j, h),
          uniformFloat(reverseBits(laineKarrasPermutation(sobolDimension1Mirrored(j), yScramble)))};
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
