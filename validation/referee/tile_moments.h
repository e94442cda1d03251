// One side of a refereed comparison as it grows render by render: for every tile and colour
// channel, the running mean and second central moment of the tile's value over the renders,
// where a render's tile value is the mean of its pixels there (the method of batch means,
// validation/compare/batch_regions.h: right however a render's pixels are correlated,
// provided the renders are independent). Kept by Welford's update (B. P. Welford 1962, "Note
// on a method for calculating corrected sums of squares and products", Technometrics 4(3)),
// so that a renders' images need not be kept, and a baseline (baseline.h) can store exactly
// these numbers.
#pragma once

#include <verity/stats/pixel_statistics.h>
#include <verity/stats/tile_grid.h>
#include <verity/stats/welch_t.h>

#include <array>
#include <string>
#include <vector>

#include "film/image_io.h"

namespace verity::validation {

class TileMoments {
 public:
  struct Moments {
    double mean = 0;
    double m2 = 0;  // Σ (x − mean)² over the renders
  };

  explicit TileMoments(int tileSize = 16);
  // Moments kept elsewhere (a baseline): `tiles` holds grid.count() tiles, tile-major.
  TileMoments(TileGrid grid, int renders, std::vector<std::array<Moments, kChannels>> tiles);

  // Adds one render. Its R, G and B are found by rgb_channels.h (`layer`). Throws VerityError
  // naming `label` when it has no R, G and B, another size than the earlier renders, or a
  // value that is not finite.
  void add(const ImageChannels& image, const std::string& label, const std::string& layer = "");

  int renders() const { return renders_; }
  const TileGrid& grid() const { return grid_; }
  const std::string& firstLabel() const { return firstLabel_; }
  const std::array<Moments, kChannels>& tile(int index) const { return tiles_[index]; }
  // The estimate of the tile's expectation: the mean over the renders, its variance S²/N with
  // N − 1 degrees of freedom (needs N ≥ 2; std::logic_error otherwise).
  MeanEstimate estimate(int tile, int channel) const;
  // Each pixel's mean over the renders (planes R, G and B, linear), to show under a picture's
  // z-scores (z_score_image.h). Moments kept elsewhere (a baseline) have no pixels: no planes.
  ImageChannels meanImage() const;

 private:
  TileGrid grid_;
  int renders_ = 0;
  std::string firstLabel_;
  std::vector<std::array<Moments, kChannels>> tiles_;
  std::array<std::vector<double>, kChannels> pixelMeans_;  // row-major; empty for a baseline
};

}  // namespace verity::validation
