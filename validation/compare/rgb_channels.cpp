#include "validation/compare/rgb_channels.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <set>
#include <vector>

#include "core/error.h"

namespace verity::validation {

namespace {

std::array<std::string, kChannels> layerChannels(const std::string& layer) {
  std::array<std::string, kChannels> names;
  for (int c = 0; c < kChannels; ++c)
    names[c] = layer.empty() ? kChannelNames[c] : layer + "." + kChannelNames[c];
  return names;
}

bool hasAll(const ImageChannels& image, const std::array<std::string, kChannels>& names) {
  for (const std::string& n : names)
    if (!image.planes.count(n)) return false;
  return true;
}

std::string channelList(const ImageChannels& image) {
  std::vector<std::string> names;
  for (const auto& [name, plane] : image.planes) names.push_back(name);
  return names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace

std::array<std::string, kChannels> rgbChannelNames(const ImageChannels& image,
                                                   const std::string& file,
                                                   const std::string& layer) {
  if (!layer.empty()) {
    const auto names = layerChannels(layer);
    if (!hasAll(image, names))
      throw VerityError(file, "",
                        fmt::format("the image has no layer \"{}\" with channels {}, {} and {} "
                                    "(its channels: {})",
                                    layer, names[0], names[1], names[2], channelList(image)));
    return names;
  }
  if (hasAll(image, layerChannels(""))) return layerChannels("");
  // Layers P with P.R: candidates; those with P.G and P.B as well are matches.
  std::set<std::string> matches;
  for (const auto& [name, plane] : image.planes) {
    const std::string suffix = std::string(".") + kChannelNames[0];
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
      const std::string prefix = name.substr(0, name.size() - suffix.size());
      if (hasAll(image, layerChannels(prefix))) matches.insert(prefix);
    }
  }
  if (matches.size() == 1) return layerChannels(*matches.begin());
  if (matches.empty())
    throw VerityError(file, "",
                      fmt::format("the image has no R, G and B channels, neither bare nor as one "
                                  "layer's L.R, L.G and L.B (its channels: {})",
                                  channelList(image)));
  throw VerityError(file, "",
                    fmt::format("the image has R, G and B in several layers ({}): name the one "
                                "to compare with --layer",
                                fmt::join(matches, ", ")));
}

ImageChannels rgbOnly(const ImageChannels& image, const std::string& file,
                      const std::string& layer) {
  const auto names = rgbChannelNames(image, file, layer);
  ImageChannels rgb;
  rgb.width = image.width;
  rgb.height = image.height;
  rgb.attributes = image.attributes;
  for (int c = 0; c < kChannels; ++c) rgb.planes[kChannelNames[c]] = image.planes.at(names[c]);
  return rgb;
}

}  // namespace verity::validation
