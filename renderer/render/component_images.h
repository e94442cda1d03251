// The films of the components a render records besides its image (--strategies,
// --path-lengths; see integrators/component_layout.h). They follow the image's passes: each
// pass every pixel of every component gets one sample, its camera sample's part plus the
// splats of that component landing on it, added in tile order as the image's splats are,
// so the components stay bit-identical for any thread count and add up to the image.
#pragma once

#include <vector>

#include "film/film.h"
#include "integrators/component_recorder.h"

namespace verity {

class ComponentImages {
 public:
  ComponentImages(const ComponentLayout& layout, const Vector2i& resolution);
  // The recorders point into this object.
  ComponentImages(const ComponentImages&) = delete;
  ComponentImages& operator=(const ComponentImages&) = delete;

  // Memory the films of `images` components at `resolution` take, in bytes.
  static double bytesNeeded(uint64_t images, const Vector2i& resolution);

  const ComponentLayout& layout() const { return layout_; }
  const Film& film(int component) const { return films_[component]; }

  // The renderer's side: a recorder per tile, the pass's values, and the pass's end, where
  // `valid` says which pixels' camera samples were finite (the others count as invalid in
  // every component, as in the image).
  void startPass(size_t tiles);
  ComponentRecorder& recorder(size_t tile) { return recorders_[tile]; }
  void finishPass(const std::vector<uint8_t>& valid);
  void addZeroSamples(uint32_t n);

 private:
  ComponentLayout layout_;
  Vector2i resolution_;
  std::vector<Film> films_;
  std::vector<Color3> passValues_;  // pixel-major: pixel · layout.size() + component
  std::vector<ComponentRecorder> recorders_;
};

}  // namespace verity
