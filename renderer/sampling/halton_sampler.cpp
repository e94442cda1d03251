#include "sampling/halton_sampler.h"

#include <boost/math/special_functions/prime.hpp>
#include <vector>

#include "core/hash.h"
#include "params/key.h"
#include "sampling/independent_sampler.h"

namespace verity {

namespace {

// The prime base of each dimension. boost::math::prime(n) copies its tables on every call
// (Boost 1.74): that was most of a Halton value's cost, so the primes are copied once.
const std::vector<uint32_t>& primeBases() {
  static const std::vector<uint32_t> primes = [] {
    std::vector<uint32_t> p(boost::math::max_prime + 1);
    for (unsigned i = 0; i < p.size(); ++i) p[i] = boost::math::prime(i);
    return p;
  }();
  return primes;
}

}  // namespace

void HaltonSampler::startPixelSample(const Point2i& pixel, int index) {
  pixelKey_ = (uint64_t(uint32_t(pixel.y())) << 32) | uint32_t(pixel.x());
  index_ = index;
  dimension_ = 0;
}

float HaltonSampler::sample(int dimension) const {
  if (dimension > static_cast<int>(boost::math::max_prime))  // the last prime index
    return uniformFloat(static_cast<uint32_t>(hashValues(seed_, pixelKey_, index_, dimension)));
  const uint32_t base = primeBases()[size_t(dimension)];
  return unitFloat(radicalInverse(static_cast<uint32_t>(index_), base, scramble_,
                                  hashValues(seed_, pixelKey_, dimension)));
}

float HaltonSampler::next1D() {
  return sample(dimension_++);
}

Point2f HaltonSampler::next2D() {
  const Point2f u(sample(dimension_), sample(dimension_ + 1));
  dimension_ += 2;
  return u;
}

namespace {

const Key<DigitScramble> kRandomization{
    .name = "randomization",
    .defaultValue = DigitScramble::Owen,
    .allowed = {{"owen", DigitScramble::Owen}, {"permute_digits", DigitScramble::PermuteDigits}},
    .meaning =
        "how the digits are scrambled: nested, keyed by the digits before (Owen 1995), or "
        "one permutation per digit position (Matousek 1998)"};

}  // namespace

SamplerType haltonSamplerType() {
  return {"halton",
          {},
          "Halton points per pixel, their digits scrambled per pixel and dimension",
          declarations(kRandomization),
          [](const JsonNode* node) -> std::unique_ptr<Sampler> {
            return std::make_unique<HaltonSampler>(node ? node->get(kRandomization)
                                                        : *kRandomization.defaultValue);
          }};
}

}  // namespace verity
