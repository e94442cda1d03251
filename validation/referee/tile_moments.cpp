#include "validation/referee/tile_moments.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "validation/compare/rgb_channels.h"

namespace verity::validation {

TileMoments::TileMoments(int tileSize) {
  if (tileSize < 1) throw std::invalid_argument("TileMoments: tile size below 1");
  grid_.tileSize = tileSize;
}

TileMoments::TileMoments(TileGrid grid, int renders,
                         std::vector<std::array<Moments, kChannels>> tiles)
    : grid_(grid), renders_(renders), tiles_(std::move(tiles)) {
  if (grid_.width < 1 || grid_.height < 1 || grid_.tileSize < 1 || renders_ < 0 ||
      tiles_.size() != size_t(grid_.count()))
    throw std::invalid_argument("TileMoments: tiles do not match the grid");
}

void TileMoments::add(const ImageChannels& image, const std::string& label,
                      const std::string& layer) {
  const auto names = rgbChannelNames(image, label, layer);
  if (renders_ == 0 && tiles_.empty()) {
    if (image.width < 1 || image.height < 1) throw VerityError(label, "", "the image is empty");
    grid_.width = image.width;
    grid_.height = image.height;
    tiles_.assign(grid_.count(), {});
    for (auto& plane : pixelMeans_) plane.assign(size_t(grid_.width) * grid_.height, 0.0);
    firstLabel_ = label;
  } else if (image.width != grid_.width || image.height != grid_.height) {
    throw VerityError(label, "",
                      fmt::format("{}x{} pixels, while the renders it is compared with have "
                                  "{}x{} (\"{}\")",
                                  image.width, image.height, grid_.width, grid_.height,
                                  firstLabel_.empty() ? "the baseline" : firstLabel_));
  }
  ++renders_;
  for (int c = 0; c < kChannels; ++c) {
    const std::vector<float>& plane = image.planes.at(names[c]);
    for (int ty = 0; ty < grid_.tilesY(); ++ty)
      for (int tx = 0; tx < grid_.tilesX(); ++tx) {
        const TileRect rect = grid_.rect(tx, ty);
        double sum = 0;
        for (int y = rect.y0; y < rect.y1; ++y)
          for (int x = rect.x0; x < rect.x1; ++x) {
            const float v = plane[size_t(y) * grid_.width + x];
            if (!std::isfinite(v))
              throw VerityError(label, "",
                                fmt::format("{} of pixel ({}, {}) is not finite ({}): the "
                                            "referee averages every pixel of every render",
                                            names[c], x, y, v));
            sum += v;
          }
        // Welford's update of the mean and M2 with the render's tile value.
        Moments& m = tiles_[ty * grid_.tilesX() + tx][c];
        const double value = sum / rect.area(), delta = value - m.mean;
        m.mean += delta / renders_;
        m.m2 += delta * (value - m.mean);
      }
    if (pixelMeans_[c].empty()) continue;  // renders added to a baseline's moments
    for (size_t i = 0; i < plane.size(); ++i)
      pixelMeans_[c][i] += (plane[i] - pixelMeans_[c][i]) / renders_;
  }
}

ImageChannels TileMoments::meanImage() const {
  ImageChannels image;
  image.width = grid_.width;
  image.height = grid_.height;
  if (pixelMeans_[0].empty()) return image;
  constexpr std::array<const char*, kChannels> kNames = {"R", "G", "B"};
  for (int c = 0; c < kChannels; ++c)
    image.planes[kNames[c]].assign(pixelMeans_[c].begin(), pixelMeans_[c].end());
  return image;
}

MeanEstimate TileMoments::estimate(int tile, int channel) const {
  if (renders_ < 2) throw std::logic_error("TileMoments::estimate: needs two renders");
  const Moments& m = tiles_[tile][channel];
  return sampleMean(m.mean, m.m2 / (renders_ - 1), renders_);
}

}  // namespace verity::validation
