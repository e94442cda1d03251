// Sample generators. A sampler is positioned at one (pixel, sample index) before use, and
// every value it returns is a function of (seed, pixel, sample index, dimension) alone, so
// that renders do not depend on the order or the thread in which pixels are processed.
#pragma once

#include <memory>
#include <string>

#include "core/math.h"

namespace verity {

class JsonNode;

class Sampler {
 public:
  virtual ~Sampler() = default;
  // Starts sample `index` (of samplesPerPixel()) of `pixel`.
  virtual void startPixelSample(const Point2i& pixel, int index) = 0;
  virtual float next1D() = 0;
  virtual Point2f next2D() = 0;
  virtual std::unique_ptr<Sampler> clone() const = 0;
  // Whether a pixel's samples are independent of each other, so that their spread estimates
  // the variance of their mean. Stratified and randomized quasi-Monte Carlo points are
  // negatively correlated by design: their spread overstates that variance, often by far, and
  // only independent randomizations (renders with different seeds) measure it.
  virtual bool samplesAreIndependent() const { return false; }
  int samplesPerPixel() const { return spp_; }
  void setSamplesPerPixel(int spp) { spp_ = spp; }
  void setSeed(uint64_t seed) { seed_ = seed; }
  uint64_t seed() const { return seed_; }

 protected:
  int spp_ = 1;
  uint64_t seed_ = 0;
};

// Refuses, as an error naming `file` and its sampler, a sampler whose samples are not
// independent where `use` (e.g. "the variance channels") estimates a variance from the spread
// of a pixel's own samples.
void requireIndependentSamples(const Sampler& sampler, const std::string& file,
                               const std::string& use);

// Reads the scene's "sampler" object: its "type" names an entry of the sampler registry
// (sampler_registry.h), "independent" when absent; null `node` (no object) gives the default.
std::unique_ptr<Sampler> makeSampler(const JsonNode* node);

// A sampler of the registry type `name` (any case, or an alias) with its keys at their
// defaults, as a command-line option or a test names one; an unknown name is a VerityError
// naming `option` and the types there are.
std::unique_ptr<Sampler> makeSampler(const std::string& name, const std::string& option);

}  // namespace verity
