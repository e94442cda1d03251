// Shows the shading normal at the first hit, mapped from [-1,1] to [0,1].
#pragma once

#include "integrators/integrator.h"

namespace verity {

class NormalsIntegrator : public Integrator {
 public:
  Color3 Li(const Scene& scene, Sampler&, const Ray& ray, SampleContext& context) const override {
    SurfaceInteraction si;
    ++context.stats.rays;
    if (!scene.intersect(ray, si)) return Color3::Zero();
    return 0.5f * (si.shading.n.array() + 1.0f);
  }
  bool needsEmitters() const override { return false; }
};

}  // namespace verity
