// Where an integrator reports the parts of one sample's estimate when a render asks for them
// (see component_layout.h). The renderer gives each tile a recorder writing into its pass
// buffer; integrators check SampleContext::components and do nothing more without one.
#pragma once

#include <vector>

#include "core/math.h"
#include "integrators/component_layout.h"

namespace verity {

// A contribution to another pixel than the one being sampled, of one component.
struct ComponentSplat {
  int component;
  size_t pixel;  // y · width + x
  Color3 value;
};

class ComponentRecorder {
 public:
  // `values` holds width · height · layout.size() colours, pixel-major.
  ComponentRecorder(const ComponentLayout& layout, Color3* values, const Vector2i& resolution)
      : layout_(&layout), values_(values), resolution_(resolution) {}

  void startPixel(const Point2i& pixel) {
    pixel_ = size_t(pixel.y()) * resolution_.x() + pixel.x();
  }
  void clearSplats() { splats_.clear(); }
  const std::vector<ComponentSplat>& splats() const { return splats_; }

  // Paths of `bounces` bounces found for the pixel being sampled (path tracers).
  void addPathLength(int bounces, const Color3& value) {
    add(layout_->pathLengthIndex(bounces), value);
  }
  // Strategy (s, t)'s contribution to the pixel being sampled, with and without its weight.
  void addStrategy(int s, int t, const Color3& weighted, const Color3& unweighted);
  // The same for t = 1, landing at `film` (in pixels); dropped where SampleContext::splat
  // drops the weighted value, so that the weighted images still add up to the image.
  void splatStrategy(int s, const Point2f& film, const Color3& weighted, const Color3& unweighted);

 private:
  void add(int component, const Color3& value) {
    if (component >= 0) values_[pixel_ * layout_->size() + component] += value;
  }
  void splat(int component, size_t pixel, const Color3& value) {
    if (component >= 0 && !isBlack(value)) splats_.push_back({component, pixel, value});
  }

  const ComponentLayout* layout_;
  Color3* values_;
  Vector2i resolution_;
  size_t pixel_ = 0;
  std::vector<ComponentSplat> splats_;
};

}  // namespace verity
