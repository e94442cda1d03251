// Per-pixel statistics of a rendered image: the mean of each pixel's samples, the unbiased
// sample variance of ONE sample, and the number of valid samples, per colour channel. This is
// what `verity render --variance` writes (R, G, B, variance.R/G/B, samples); the variance of
// a pixel's mean is then variance / samples. Plain arrays: reading them from an EXR is
// validation/exr_statistics.h.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace verity::validation {

inline constexpr int kChannels = 3;
inline constexpr const char* kChannelNames[kChannels] = {"R", "G", "B"};

struct PixelStatistics {
  std::string label;  // where the image came from (a file name), for error messages
  int width = 0, height = 0;
  std::array<std::vector<double>, kChannels> mean, variance;  // width·height each, row-major
  std::vector<double> samples;                                // valid samples per pixel
  std::map<std::string, std::string> attributes;              // the EXR's string attributes

  size_t index(int x, int y) const { return size_t(y) * width + x; }
};

// The statistics of every sample multiplied by `factor` (means × factor, variances ×
// factor²): a render with a uniform brightness error, to measure a comparison's power.
PixelStatistics scaledStatistics(PixelStatistics s, double factor);

}  // namespace verity::validation
