#include "validation/compare/batch_regions.h"

#include <fmt/format.h>
#include <verity/stats/tile_grid.h>

#include <algorithm>

#include "core/error.h"

namespace verity::validation {

BatchRegions::BatchRegions(std::vector<int> regionOf, int regions, std::string label)
    : regionOf_(std::move(regionOf)),
      pixels_(regions, 0),
      label_(std::move(label)),
      sum_(regions, {0, 0, 0}),
      sumSquares_(regions, {0, 0, 0}) {
  for (int r : regionOf_)
    if (r >= 0) ++pixels_.at(r);
}

void BatchRegions::addBatch(const ImageChannels& image) {
  const std::vector<float>* planes[kChannels];
  for (int c = 0; c < kChannels; ++c) {
    const auto plane = image.planes.find(kChannelNames[c]);
    if (plane == image.planes.end())
      throw VerityError(label_, "", fmt::format("a batch without channel {}", kChannelNames[c]));
    planes[c] = &plane->second;
  }
  addBatch(image.width, image.height, [&](int x, int y) {
    const size_t i = size_t(y) * image.width + x;
    return Color3((*planes[0])[i], (*planes[1])[i], (*planes[2])[i]);
  });
}

void BatchRegions::addBatch(int width, int height, const std::function<Color3(int, int)>& mean) {
  if (size_t(width) * height != regionOf_.size())
    throw VerityError(label_, "",
                      fmt::format("a batch of {}x{} pixels for a region map of {} pixels", width,
                                  height, regionOf_.size()));
  std::vector<std::array<double, kChannels>> batch(pixels_.size(), {0, 0, 0});
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int r = regionOf_[size_t(y) * width + x];
      if (r < 0) continue;
      const Color3 m = mean(x, y);
      for (int c = 0; c < kChannels; ++c) batch[r][c] += m[c];
    }
  for (size_t r = 0; r < pixels_.size(); ++r)
    for (int c = 0; c < kChannels; ++c) {
      const double v = pixels_[r] > 0 ? batch[r][c] / pixels_[r] : 0.0;
      sum_[r][c] += v;
      sumSquares_[r][c] += v * v;
    }
  ++batches_;
}

PixelStatistics BatchRegions::statistics() const {
  if (batches_ < 2) throw VerityError(label_, "", "a region's variance needs at least two batches");
  PixelStatistics s;
  s.label = label_;
  s.width = static_cast<int>(pixels_.size());
  s.height = 1;
  s.samples.resize(pixels_.size());
  for (size_t r = 0; r < pixels_.size(); ++r) s.samples[r] = pixels_[r] > 0 ? batches_ : 0;
  for (int c = 0; c < kChannels; ++c) {
    s.mean[c].resize(pixels_.size());
    s.variance[c].resize(pixels_.size());
    for (size_t r = 0; r < pixels_.size(); ++r) {
      const double mean = sum_[r][c] / batches_;
      s.mean[c][r] = mean;
      // Rounding can leave a tiny negative difference for constant values.
      s.variance[c][r] = std::max(0.0, (sumSquares_[r][c] - sum_[r][c] * mean) / (batches_ - 1));
    }
  }
  return s;
}

std::vector<int> tileRegions(int width, int height, int tileSize, int* tiles) {
  const TileGrid grid{width, height, tileSize};
  std::vector<int> region(size_t(width) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      region[size_t(y) * width + x] = (y / tileSize) * grid.tilesX() + x / tileSize;
  *tiles = grid.count();
  return region;
}

}  // namespace verity::validation
