// A comparison side that is a set of independent renders of one image, from any renderer
// (EXR files, 16- or 32-bit float, R, G and B found by rgb_channels.h), no variance channels
// needed. Each tile's estimate is the method of batch means (batch_regions.h): in each
// render the mean over the tile's usable pixels is one value, and the N renders' values give
// the tile's mean and, from their spread, its variance S²/N with N − 1 degrees of freedom.
// This holds however the pixels of one render are correlated (a light tracer's or BDPT's
// splats), provided the renders are independent (different seeds).
//
// Non-finite values are never averaged in: a pixel with a NaN or infinity in any channel of
// any render is left out of every render (and of the other side), and counted per file.
#pragma once

#include <filesystem>
#include <vector>

#include "film/image_io.h"
#include "validation/compare/comparison_side.h"

namespace verity::validation {

class RenderSetSide : public ComparisonSide {
 public:
  // A sample variance needs two values.
  static constexpr int kMinimumRenders = 2;

  // The renders `images` read from `files` (same order). Throws VerityError naming the file
  // when it has no R, G and B (rgb_channels.h, `layer`), another resolution than the
  // first or the same pixels as another, and when there are fewer than kMinimumRenders.
  RenderSetSide(std::vector<std::string> files, const std::vector<ImageChannels>& images,
                const std::string& layer);
  // Reads the files (readExr) and keeps only their R, G and B.
  static RenderSetSide load(const std::vector<std::filesystem::path>& files,
                            const std::string& layer);

  const std::string& label() const override { return label_; }
  int width() const override { return renders_.front().width; }
  int height() const override { return renders_.front().height; }
  std::vector<char> usablePixels(int minSamples) const override { return finite_; }
  std::vector<std::array<MeanEstimate, kChannels>> tileEstimates(
      const TileGrid& grid, const std::vector<char>& usable) const override;
  SideSummary summary() const override;
  ImageChannels meanImage() const override;
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> attributes()
      const override;

 private:
  // Two renders with the same R, G and B (one render written twice, in other files) are
  // refused, naming both files.
  void requireDistinctPixels() const;

  std::vector<std::string> files_;
  std::string label_;
  std::vector<ImageChannels> renders_;  // planes R, G and B only
  std::vector<int> nonfinite_;          // pixels with a non-finite value, per render
  std::vector<char> finite_;            // 1 where every render is finite
};

}  // namespace verity::validation
