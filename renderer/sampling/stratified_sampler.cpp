#include "sampling/stratified_sampler.h"

#include <bit>

#include "core/hash.h"
#include "sampling/independent_sampler.h"

namespace verity {

StratifiedSampler::Round StratifiedSampler::roundOf(int index, int spp) {
  if (spp <= kLargestRound) return {0, 0, spp};
  if (index < kFirstRound) return {0, 0, kFirstRound};
  // Round k >= 1 holds samples [16 2^(k-1), 16 2^k); the last is cut at spp.
  const int k = std::bit_width(static_cast<unsigned>(index / kFirstRound));
  const int first = kFirstRound << (k - 1);
  return {k, first, std::min(first, spp - first)};
}

namespace {
// `value`, in [lo, hi), as a float inside [lo, hi) too: rounding to the nearest float could
// carry a value just below a stratum's edge onto it.
float floatWithin(double value, double lo, double hi) {
  float f = static_cast<float>(value);
  while (double(f) >= hi) f = std::nextafter(f, 0.0f);
  while (double(f) < lo) f = std::nextafter(f, 1.0f);
  return f;
}
}  // namespace

Point2f stratumPoint(uint32_t s, uint32_t n, double jitterX, double jitterY) {
  const uint32_t columns = std::max<uint32_t>(1, std::lround(std::sqrt(double(n))));
  const uint32_t rows = n / columns, taller = n % columns;  // the first `taller` hold rows + 1
  uint32_t column, row, height, before;
  if (s < taller * (rows + 1)) {
    column = s / (rows + 1), row = s % (rows + 1), height = rows + 1;
    before = column * (rows + 1);
  } else {
    const uint32_t t = s - taller * (rows + 1);
    column = taller + t / rows, row = t % rows, height = rows;
    before = taller * (rows + 1) + (t / rows) * rows;
  }
  // A column of `height` cells is height / n wide, so that each cell's area is 1 / n.
  return {
      floatWithin((before + height * jitterX) / n, double(before) / n, double(before + height) / n),
      floatWithin((row + jitterY) / height, double(row) / height, double(row + 1) / height)};
}

void StratifiedSampler::startPixelSample(const Point2i& pixel, int index) {
  pixelKey_ = (uint64_t(uint32_t(pixel.y())) << 32) | uint32_t(pixel.x());
  round_ = roundOf(index, spp_);
  index_ = index - round_.first;
  dimension_ = 0;
  rng_.seed(hashValues(seed_, pixelKey_, 17), hashValues(seed_, pixelKey_, index));
}

float StratifiedSampler::next1D() {
  const uint64_t key = hashValues(seed_, pixelKey_, dimension_++, round_.number);
  const uint32_t stratum = permuteIndex(static_cast<uint32_t>(index_), round_.size, key);
  const double n = round_.size;
  return floatWithin((stratum + double(uniformFloat(rng_()))) / n, stratum / n, (stratum + 1) / n);
}

Point2f StratifiedSampler::next2D() {
  const uint64_t key = hashValues(seed_, pixelKey_, dimension_, round_.number);
  dimension_ += 2;
  const uint32_t stratum = permuteIndex(static_cast<uint32_t>(index_), round_.size, key);
  const float jx = uniformFloat(rng_()), jy = uniformFloat(rng_());
  return stratumPoint(stratum, round_.size, jx, jy);
}

SamplerType stratifiedSamplerType() {
  return {"stratified",
          {},
          "jittered strata per pixel and dimension, for any count",
          {},  // no keys of its own
          [](const JsonNode*) -> std::unique_ptr<Sampler> {
            return std::make_unique<StratifiedSampler>();
          }};
}

}  // namespace verity
