// One side of an image comparison: what it estimates for every tile. A side is one image
// with per-pixel variances (variance_image_side.h) or a set of independent renders
// (render_set_side.h); the comparison (image_comparison.h) pools both sides over the same
// pixels.
#pragma once

#include <verity/stats/tile_grid.h>
#include <verity/stats/welch_t.h>

#include <array>
#include <map>
#include <string>
#include <vector>

#include "film/image_io.h"

namespace verity::validation {

// What a side was made of, for the report.
struct SideSummary {
  bool renderSet = false;          // a set of renders, or one image with variance channels
  std::vector<std::string> files;  // for an image built in memory: its label
  // Pixels with a non-finite value in each file of a set (left out of both sides).
  std::vector<int> nonfinitePixels;
  int renders() const { return renderSet ? static_cast<int>(files.size()) : 1; }
};

class ComparisonSide {
 public:
  virtual ~ComparisonSide() = default;

  virtual const std::string& label() const = 0;  // names the side in errors
  virtual int width() const = 0;
  virtual int height() const = 0;
  // 1 for each pixel this side can estimate, row-major: in an image with variances, at
  // least `minSamples` samples; in a set, finite values in every render.
  virtual std::vector<char> usablePixels(int minSamples) const = 0;
  // Every tile's estimated mean per channel over the pixels `usable` marks (tile-major, as
  // TileGrid numbers them). Each marked pixel must be usable on this side.
  virtual std::vector<std::array<MeanEstimate, kChannels>> tileEstimates(
      const TileGrid& grid, const std::vector<char>& usable) const = 0;
  virtual SideSummary summary() const = 0;
  // What the side estimates per pixel, for showing under the z-scores (z_score_image.h):
  // planes R, G and B, linear. A set's pixel is the mean of its renders (NaN where a render
  // is not finite); an image with variances gives its means.
  virtual ImageChannels meanImage() const = 0;
  // Each file's label and string attributes (for warnings: renders sharing a seed).
  virtual std::vector<std::pair<std::string, std::map<std::string, std::string>>> attributes()
      const = 0;
};

}  // namespace verity::validation
