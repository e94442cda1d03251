// Estimators of the radiance arriving along a camera ray.
#pragma once

#include <memory>
#include <string>

#include "core/ray.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

namespace verity {

// Counters one sample adds to; summed per tile so that totals are deterministic.
struct PathStats {
  uint64_t rays = 0;  // closest-hit and shadow queries
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual Color3 Li(const Scene& scene, Sampler& sampler, const Ray& ray,
                    PathStats& stats) const = 0;
  // Radiance integrators see nothing in a scene without emitters: the renderer then writes
  // black without tracing a ray.
  virtual bool needsEmitters() const { return true; }
};

}  // namespace verity
