// A comparison side that is one image with per-pixel means, variances and sample counts (a
// Verity EXR rendered with --variance): each tile's estimate pools its pixels
// (verity/stats/tile_pooling.h), with Satterthwaite's degrees of freedom from the
// pixels' sample counts.
#pragma once

#include <verity/stats/pixel_statistics.h>

#include "validation/compare/comparison_side.h"

namespace verity::validation {

class VarianceImageSide : public ComparisonSide {
 public:
  explicit VarianceImageSide(PixelStatistics stats) : stats_(std::move(stats)) {}

  const std::string& label() const override { return stats_.label; }
  int width() const override { return stats_.width; }
  int height() const override { return stats_.height; }
  std::vector<char> usablePixels(int minSamples) const override;
  std::vector<std::array<MeanEstimate, kChannels>> tileEstimates(
      const TileGrid& grid, const std::vector<char>& usable) const override;
  SideSummary summary() const override;
  ImageChannels meanImage() const override;
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> attributes()
      const override {
    return {{stats_.label, stats_.attributes}};
  }

 private:
  PixelStatistics stats_;
};

}  // namespace verity::validation
