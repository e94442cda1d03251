// Tile moments (tile_moments.h) as a side of validation/compare's comparison, so that each
// round of the referee is decided by the same per-tile Welch tests and Holm procedure as
// `verity compare`, and reports, JSON and z-images come from the same ComparisonResult.
#pragma once

#include <string>

#include "validation/compare/comparison_side.h"
#include "validation/referee/tile_moments.h"

namespace verity::validation {

class MomentsSide : public ComparisonSide {
 public:
  // `moments` must outlive the side and have at least two renders.
  MomentsSide(const TileMoments& moments, std::string label);

  const std::string& label() const override { return label_; }
  int width() const override { return moments_.grid().width; }
  int height() const override { return moments_.grid().height; }
  // Every pixel: the tile values average them all.
  std::vector<char> usablePixels(int) const override;
  // The moments' estimates; `grid` must be the moments' grid (std::invalid_argument).
  std::vector<std::array<MeanEstimate, kChannels>> tileEstimates(
      const TileGrid& grid, const std::vector<char>& usable) const override;
  SideSummary summary() const override;
  ImageChannels meanImage() const override { return moments_.meanImage(); }
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> attributes()
      const override {
    return {};
  }

 private:
  const TileMoments& moments_;
  std::string label_;
};

}  // namespace verity::validation
