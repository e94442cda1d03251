#include "validation/compare/exr_statistics.h"

#include <fmt/format.h>

#include <cmath>

#include "core/error.h"

namespace verity::validation {

PixelStatistics pixelStatistics(const ImageChannels& image, const std::string& label) {
  PixelStatistics stats;
  stats.label = label;
  stats.width = image.width;
  stats.height = image.height;
  stats.attributes = image.attributes;
  if (image.width <= 0 || image.height <= 0) throw VerityError(label, "", "the image is empty");
  const size_t n = size_t(image.width) * image.height;

  auto plane = [&](const std::string& name, const char* advice) -> const std::vector<float>& {
    auto it = image.planes.find(name);
    if (it == image.planes.end())
      throw VerityError(label, "", fmt::format("the image has no \"{}\" channel{}", name, advice));
    if (it->second.size() != n)
      throw VerityError(label, "",
                        fmt::format("channel \"{}\" has {} values for {}x{} pixels", name,
                                    it->second.size(), image.width, image.height));
    return it->second;
  };
  auto where = [&](size_t i) {
    return fmt::format("pixel ({}, {})", i % image.width, i / image.width);
  };
  constexpr const char* kRenderWithVariance =
      ": a statistical comparison needs each pixel's sample variance and sample count; "
      "render the image with `verity render --variance`";

  for (int c = 0; c < kChannels; ++c) {
    const auto& m = plane(kChannelNames[c], "");
    const auto& v = plane(std::string("variance.") + kChannelNames[c], kRenderWithVariance);
    stats.mean[c].resize(n);
    stats.variance[c].resize(n);
    for (size_t i = 0; i < n; ++i) {
      if (!std::isfinite(m[i]))
        throw VerityError(
            label, "",
            fmt::format("{} of {} is not finite ({})", kChannelNames[c], where(i), m[i]));
      if (!std::isfinite(v[i]) || v[i] < 0)
        throw VerityError(label, "",
                          fmt::format("variance.{} of {} is {}: a variance must be finite and "
                                      "non-negative",
                                      kChannelNames[c], where(i), v[i]));
      stats.mean[c][i] = m[i];
      stats.variance[c][i] = v[i];
    }
  }
  const auto& s = plane("samples", kRenderWithVariance);
  stats.samples.resize(n);
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s[i]) || s[i] < 0 || s[i] != std::floor(s[i]))
      throw VerityError(label, "",
                        fmt::format("samples of {} is {}: a sample count must be a whole number "
                                    "at least 0",
                                    where(i), s[i]));
    stats.samples[i] = s[i];
  }
  return stats;
}

PixelStatistics loadPixelStatistics(const std::filesystem::path& file) {
  return pixelStatistics(readExr(file), file.string());
}

}  // namespace verity::validation
