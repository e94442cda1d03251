#include "validation/compare/display_image.h"

#include <verity/stats/pixel_statistics.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "film/srgb.h"

namespace verity::validation {

namespace {

constexpr double kKey = 0.18;  // Reinhard et al.'s middle grey
// Rec. 709 luminance of linear RGB.
constexpr double kLuminance[kChannels] = {0.2126, 0.7152, 0.0722};

unsigned char encode(double linear) {
  return static_cast<unsigned char>(
      std::lround(255 * linearToSrgb(static_cast<float>(std::clamp(linear, 0.0, 1.0)))));
}

}  // namespace

DisplayImage toneMapForDisplay(const ImageChannels& image) {
  const std::vector<float>* planes[kChannels];
  for (int c = 0; c < kChannels; ++c) {
    const auto it = image.planes.find(kChannelNames[c]);
    if (it == image.planes.end())
      throw std::invalid_argument(std::string("toneMapForDisplay: the image has no plane ") +
                                  kChannelNames[c]);
    planes[c] = &it->second;
  }
  const size_t n = size_t(image.width) * image.height;
  std::vector<double> luminance(n, 0.0);
  std::vector<char> finite(n, 1);
  for (size_t i = 0; i < n; ++i)
    for (int c = 0; c < kChannels; ++c) {
      const double v = (*planes[c])[i];
      finite[i] &= std::isfinite(v);
      luminance[i] += kLuminance[c] * std::max(0.0, v);
    }
  // Eq. 1 over the pixels with light: black background would otherwise pull the average
  // (and so the exposure) to its δ.
  double logSum = 0;
  int lit = 0;
  for (size_t i = 0; i < n; ++i)
    if (finite[i] && luminance[i] > 0) logSum += std::log(luminance[i]), ++lit;
  const double exposure = lit > 0 ? kKey / std::exp(logSum / lit) : 1.0;  // eq. 2

  DisplayImage out;
  out.width = image.width;
  out.height = image.height;
  out.colour.assign(n, Rgb8{0, 0, 0});
  out.grey.assign(n, Rgb8{0, 0, 0});
  for (size_t i = 0; i < n; ++i) {
    if (!finite[i]) continue;
    const double scaled = exposure * luminance[i];
    const double gain = exposure / (1 + scaled);  // eq. 3, applied to each channel
    for (int c = 0; c < kChannels; ++c)
      out.colour[i][c] = encode(gain * std::max(0.0, double((*planes[c])[i])));
    const unsigned char g = encode(scaled / (1 + scaled));
    out.grey[i] = {g, g, g};
  }
  return out;
}

}  // namespace verity::validation
