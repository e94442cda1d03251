#include "validation/referee/moments_side.h"

#include <stdexcept>

namespace verity::validation {

MomentsSide::MomentsSide(const TileMoments& moments, std::string label)
    : moments_(moments), label_(std::move(label)) {
  if (moments.renders() < 2) throw std::invalid_argument("MomentsSide: needs two renders");
}

std::vector<char> MomentsSide::usablePixels(int) const {
  return std::vector<char>(size_t(width()) * height(), 1);
}

std::vector<std::array<MeanEstimate, kChannels>> MomentsSide::tileEstimates(
    const TileGrid& grid, const std::vector<char>&) const {
  const TileGrid& own = moments_.grid();
  if (grid.width != own.width || grid.height != own.height || grid.tileSize != own.tileSize)
    throw std::invalid_argument("MomentsSide: another tile grid than the moments'");
  std::vector<std::array<MeanEstimate, kChannels>> estimates(own.count());
  for (int t = 0; t < own.count(); ++t)
    for (int c = 0; c < kChannels; ++c) estimates[t][c] = moments_.estimate(t, c);
  return estimates;
}

SideSummary MomentsSide::summary() const {
  SideSummary s;
  s.renderSet = true;
  s.files.assign(moments_.renders(), label_);
  s.nonfinitePixels.assign(moments_.renders(), 0);
  return s;
}

}  // namespace verity::validation
