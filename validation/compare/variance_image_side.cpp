#include "validation/compare/variance_image_side.h"

#include <verity/stats/tile_pooling.h>

namespace verity::validation {

std::vector<char> VarianceImageSide::usablePixels(int minSamples) const {
  return pixelsWithSamples(stats_, minSamples);
}

std::vector<std::array<MeanEstimate, kChannels>> VarianceImageSide::tileEstimates(
    const TileGrid& grid, const std::vector<char>& usable) const {
  std::vector<std::array<MeanEstimate, kChannels>> tiles(grid.count());
  for (int ty = 0; ty < grid.tilesY(); ++ty)
    for (int tx = 0; tx < grid.tilesX(); ++tx)
      for (int c = 0; c < kChannels; ++c) {
        int pixels = 0;
        tiles[ty * grid.tilesX() + tx][c] =
            poolPixels(stats_, grid.rect(tx, ty), c, usable, &pixels);
      }
  return tiles;
}

ImageChannels VarianceImageSide::meanImage() const {
  ImageChannels image;
  image.width = stats_.width;
  image.height = stats_.height;
  for (int c = 0; c < kChannels; ++c)
    image.planes[kChannelNames[c]].assign(stats_.mean[c].begin(), stats_.mean[c].end());
  return image;
}

SideSummary VarianceImageSide::summary() const {
  SideSummary s;
  s.files = {stats_.label};
  return s;
}

}  // namespace verity::validation
