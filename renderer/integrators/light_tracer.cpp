#include "integrators/light_tracer.h"

#include "integrators/bdpt_connect.h"
#include "integrators/bdpt_subpath.h"

namespace verity {

Color3 LightTracer::Li(const Scene& scene, Sampler& sampler, const Ray&,
                       SampleContext& context) const {
  thread_local std::vector<PathVertex> light;
  traceLightSubpath(scene, sampler, maxBounces_ + 1, roulette_, light, context.stats);
  const Vector2i& resolution = scene.camera().resolution();
  for (int s = 1; s <= static_cast<int>(light.size()); ++s) {
    PathVertex lens;
    Point2f film;
    // The background seen directly has no surface point to connect from: its ray to the lens
    // is chosen along the direction the subpath started with.
    const bool background = s == 1 && light[0].atInfinity();
    const Color3 c = background
                         ? backgroundCameraContribution(scene, sampler, light, film, context.stats)
                         : cameraContribution(scene, sampler, light, s, lens, film, context.stats);
    if (isBlack(c)) continue;
    context.splat(film, resolution, c);
    // Strategy (s, 1) alone: its weight is one.
    if (context.components) context.components->splatStrategy(s, film, c, c);
  }
  return Color3::Zero();
}

}  // namespace verity
