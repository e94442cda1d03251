#include "render/component_images.h"

namespace verity {

ComponentImages::ComponentImages(const ComponentLayout& layout, const Vector2i& resolution)
    : layout_(layout),
      resolution_(resolution),
      films_(layout.size(), Film(resolution)),
      passValues_(size_t(resolution.x()) * resolution.y() * layout.size()) {}

double ComponentImages::bytesNeeded(uint64_t images, const Vector2i& resolution) {
  // A film's double sums and sums of squares and its two counts, and the pass value.
  const double perPixel = 2 * sizeof(Eigen::Array3d) + 2 * sizeof(uint32_t) + sizeof(Color3);
  return perPixel * resolution.x() * resolution.y() * double(images);
}

void ComponentImages::startPass(size_t tiles) {
  std::fill(passValues_.begin(), passValues_.end(), Color3::Zero());
  if (recorders_.size() != tiles)
    recorders_.assign(tiles, ComponentRecorder(layout_, passValues_.data(), resolution_));
  for (ComponentRecorder& r : recorders_) r.clearSplats();
}

void ComponentImages::finishPass(const std::vector<uint8_t>& valid) {
  const size_t n = layout_.size();
  for (const ComponentRecorder& r : recorders_)
    for (const ComponentSplat& s : r.splats()) passValues_[s.pixel * n + s.component] += s.value;
  for (int y = 0; y < resolution_.y(); ++y)
    for (int x = 0; x < resolution_.x(); ++x) {
      const size_t pixel = size_t(y) * resolution_.x() + x;
      for (size_t c = 0; c < n; ++c) {
        if (valid[pixel])
          films_[c].addSample(x, y, passValues_[pixel * n + c]);
        else
          films_[c].addInvalidSample(x, y);
      }
    }
}

void ComponentImages::addZeroSamples(uint32_t n) {
  for (Film& f : films_) f.addZeroSamples(n);
}

}  // namespace verity
