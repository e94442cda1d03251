// Which channels of an EXR from any renderer are its R, G and B. The rule (documented in
// docs/comparing.md):
//   1. with a layer named (--layer L): exactly L.R, L.G and L.B;
//   2. otherwise R, G and B when all three exist: OpenEXR's default layer, which pbrt-v3,
//      pbrt-v4, Mitsuba and Verity write (other channels, such as pbrt-v4's Albedo.R or
//      Verity's variance.R, are then ignored);
//   3. otherwise the one layer P with P.R, P.G and P.B (default.R, rgb.R,
//      ViewLayer.Combined.R, ...).
// No match, or several layers in step 3, is an error naming the file and listing what it has.
#pragma once

#include <verity/stats/pixel_statistics.h>

#include <array>
#include <string>

#include "film/image_io.h"

namespace verity::validation {

// The names of the R, G and B planes of `image` read from `file`; throws VerityError.
std::array<std::string, kChannels> rgbChannelNames(const ImageChannels& image,
                                                   const std::string& file,
                                                   const std::string& layer = "");
// The image with only its R, G and B (found so), renamed R, G and B.
ImageChannels rgbOnly(const ImageChannels& image, const std::string& file,
                      const std::string& layer);

}  // namespace verity::validation
