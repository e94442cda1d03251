// Estimators of the radiance arriving along a camera ray.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/ray.h"
#include "integrators/component_recorder.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

namespace verity {

// Counters one sample adds to; summed per tile so that totals are deterministic.
struct PathStats {
  uint64_t rays = 0;  // closest-hit and shadow queries
};

// Contributions that land on another pixel than the one being sampled (light paths
// connected to the camera). Each tile keeps its own list; the renderer adds the lists to
// the image in tile order, so splatting stays deterministic.
struct Splat {
  Point2i pixel;
  Color3 value;
};

// The pixel containing film position `film` (in pixels), or none outside the image.
inline std::optional<Point2i> filmPixel(const Point2f& film, const Vector2i& resolution) {
  const int x = static_cast<int>(std::floor(film.x())), y = static_cast<int>(std::floor(film.y()));
  if (x < 0 || y < 0 || x >= resolution.x() || y >= resolution.y()) return std::nullopt;
  return Point2i(x, y);
}

// What one camera sample may write besides its own radiance.
struct SampleContext {
  PathStats stats;
  std::vector<Splat> splats;
  uint64_t invalidSplats = 0;  // NaN or Inf splats, dropped
  // The parts of the estimate to record (--strategies, --path-lengths); null: none.
  ComponentRecorder* components = nullptr;

  // `film` is a position in pixels; positions outside the image are dropped. The value is
  // this sample's estimate for that pixel (it is added to the pixel's sample of this pass).
  void splat(const Point2f& film, const Vector2i& resolution, const Color3& value) {
    if (!value.allFinite()) {
      ++invalidSplats;
      return;
    }
    const auto pixel = filmPixel(film, resolution);
    if (pixel && !isBlack(value)) splats.push_back({*pixel, value});
  }
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual Color3 Li(const Scene& scene, Sampler& sampler, const Ray& ray,
                    SampleContext& context) const = 0;
  // Radiance integrators see nothing in a scene without emitters: the renderer then writes
  // black without tracing a ray.
  virtual bool needsEmitters() const { return true; }
};

}  // namespace verity
