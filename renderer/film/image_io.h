// Writing and reading images: OpenEXR for high dynamic range (optionally with variance and
// sample-count channels), 8-bit PNG through the exact sRGB curve.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "film/film.h"

namespace verity {

// Named planes of one image, each width·height floats, row 0 at the top.
struct ImageChannels {
  int width = 0, height = 0;
  std::map<std::string, std::vector<float>> planes;
  std::map<std::string, std::string> attributes;  // written as string attributes
};

// R, G, B from the film's means; with `withVariance`, also variance.R/G/B (sample variance
// of one sample) and "samples" (valid sample count), so that a pixel's mean has variance
// variance / samples.
ImageChannels filmChannels(const Film& film, bool withVariance);

// With `halfFloat`, every plane but "samples" (counts stay exact in 32-bit floats) is stored
// as 16-bit floats; a value beyond their range (|v| > 65504, or NaN) is refused with an error
// rather than written as Inf.
void writeExr(const std::filesystem::path& file, const ImageChannels& image,
              bool halfFloat = false);
// The largest value the 16-bit float planes of writeExr can hold.
inline constexpr float kHalfFloatMax = 65504.0f;
// Whether writeExr(..., halfFloat = true) can store every value of `image`.
bool fitsHalfFloat(const ImageChannels& image);
ImageChannels readExr(const std::filesystem::path& file);
// Gain 1, exact sRGB curve, clamp, no tone mapping.
void writePng(const std::filesystem::path& file, const ImageChannels& image);

}  // namespace verity
