// A Verity EXR written with `verity render --variance` read as per-pixel statistics
// (verity/stats/pixel_statistics.h).
#pragma once

#include <verity/stats/pixel_statistics.h>

#include <filesystem>
#include <string>

#include "film/image_io.h"

namespace verity::validation {

// Checks the planes (R, G, B, variance.R/G/B, samples) and their values; throws VerityError
// naming `label` when a plane is missing (render with --variance), or a value is negative,
// not finite, or a sample count is not a whole number.
PixelStatistics pixelStatistics(const ImageChannels& image, const std::string& label);
// readExr followed by pixelStatistics.
PixelStatistics loadPixelStatistics(const std::filesystem::path& file);

}  // namespace verity::validation
