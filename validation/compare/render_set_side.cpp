#include "validation/compare/render_set_side.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string_view>

#include "core/error.h"
#include "validation/compare/batch_regions.h"
#include "validation/compare/rgb_channels.h"

namespace verity::validation {

RenderSetSide::RenderSetSide(std::vector<std::string> files,
                             const std::vector<ImageChannels>& images, const std::string& layer)
    : files_(std::move(files)) {
  if (images.size() != files_.size())
    throw std::invalid_argument("RenderSetSide: one file name per image");
  if (files_.size() < size_t(kMinimumRenders))
    throw VerityError(files_.empty() ? "" : files_.front(), "",
                      fmt::format("a set of renders needs at least {} renders (a variance "
                                  "from their spread), not {}",
                                  kMinimumRenders, files_.size()));
  label_ = fmt::format("{} and {} more", files_.front(), files_.size() - 1);
  for (size_t r = 0; r < images.size(); ++r) {
    renders_.push_back(rgbOnly(images[r], files_[r], layer));
    const ImageChannels& first = renders_.front();
    if (images[r].width != first.width || images[r].height != first.height)
      throw VerityError(
          files_[r], "",
          fmt::format("{}x{} pixels, while {} of the same set has {}x{}", images[r].width,
                      images[r].height, files_.front(), first.width, first.height));
  }
  requireDistinctPixels();
  const size_t n = size_t(width()) * height();
  finite_.assign(n, 1);
  for (const ImageChannels& render : renders_) {
    const std::vector<float>* planes[kChannels];
    for (int c = 0; c < kChannels; ++c) planes[c] = &render.planes.at(kChannelNames[c]);
    int count = 0;
    for (size_t i = 0; i < n; ++i) {
      bool finite = true;
      for (int c = 0; c < kChannels; ++c) finite &= std::isfinite((*planes[c])[i]);
      if (!finite) {
        ++count;
        finite_[i] = 0;
      }
    }
    nonfinite_.push_back(count);
  }
}

void RenderSetSide::requireDistinctPixels() const {
  // Hashes first, so that only renders with equal hashes are compared value by value.
  std::vector<size_t> digests;
  for (const ImageChannels& render : renders_) {
    size_t digest = 0;
    for (int c = 0; c < kChannels; ++c) {
      const std::vector<float>& plane = render.planes.at(kChannelNames[c]);
      const std::string_view bytes(reinterpret_cast<const char*>(plane.data()),
                                   plane.size() * sizeof(float));
      digest = digest * 1000003 + std::hash<std::string_view>{}(bytes);
    }
    digests.push_back(digest);
  }
  for (size_t i = 0; i < renders_.size(); ++i)
    for (size_t j = i + 1; j < renders_.size(); ++j)
      if (digests[i] == digests[j] && renders_[i].planes == renders_[j].planes)
        throw VerityError(files_[j], "",
                          fmt::format("has the same R, G and B as \"{}\": one render written "
                                      "twice is not two independent renders",
                                      files_[i]));
}

std::vector<std::array<MeanEstimate, kChannels>> RenderSetSide::tileEstimates(
    const TileGrid& grid, const std::vector<char>& usable) const {
  int tiles = 0;
  std::vector<int> regionOf = tileRegions(grid.width, grid.height, grid.tileSize, &tiles);
  for (size_t i = 0; i < regionOf.size(); ++i)
    if (!usable[i]) regionOf[i] = -1;
  BatchRegions regions(std::move(regionOf), tiles, label_);
  for (const ImageChannels& render : renders_) regions.addBatch(render);
  const PixelStatistics batches = regions.statistics();
  std::vector<std::array<MeanEstimate, kChannels>> estimates(tiles);
  for (int t = 0; t < tiles; ++t)
    if (batches.samples[t] > 0)
      for (int c = 0; c < kChannels; ++c)
        estimates[t][c] =
            sampleMean(batches.mean[c][t], batches.variance[c][t], batches.samples[t]);
  return estimates;
}

ImageChannels RenderSetSide::meanImage() const {
  ImageChannels mean;
  mean.width = width();
  mean.height = height();
  for (const char* name : kChannelNames) {
    std::vector<float>& sum = mean.planes[name];
    sum.assign(size_t(width()) * height(), 0.0f);
    for (const ImageChannels& render : renders_) {
      const std::vector<float>& plane = render.planes.at(name);
      for (size_t i = 0; i < sum.size(); ++i) sum[i] += plane[i];
    }
    for (float& v : sum) v /= renders_.size();
  }
  return mean;
}

SideSummary RenderSetSide::summary() const {
  SideSummary s;
  s.renderSet = true;
  s.files = files_;
  s.nonfinitePixels = nonfinite_;
  return s;
}

std::vector<std::pair<std::string, std::map<std::string, std::string>>> RenderSetSide::attributes()
    const {
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> out;
  for (size_t r = 0; r < files_.size(); ++r) out.emplace_back(files_[r], renders_[r].attributes);
  return out;
}

}  // namespace verity::validation
