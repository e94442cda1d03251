// Ambient occlusion: the cosine-weighted fraction of the hemisphere above the first hit that
// is open within `distance`; escaping camera rays see 1.
#pragma once

#include "integrators/integrator.h"

namespace verity {

class AmbientOcclusion : public Integrator {
 public:
  explicit AmbientOcclusion(float distance) : distance_(distance) {}
  Color3 Li(const Scene& scene, Sampler& sampler, const Ray& ray,
            SampleContext& context) const override;
  bool needsEmitters() const override { return false; }

 private:
  float distance_;
};

}  // namespace verity
