#include "integrators/ambient_occlusion.h"

#include "sampling/warp.h"

namespace verity {

Color3 AmbientOcclusion::Li(const Scene& scene, Sampler& sampler, const Ray& ray,
                            SampleContext& context) const {
  SurfaceInteraction si;
  ++context.stats.rays;
  if (!scene.intersect(ray, si)) return Color3::Ones();
  // The hemisphere on the side the camera ray arrived from.
  const Normal3f n = si.ng.dot(ray.d) < 0 ? si.ng : Normal3f(-si.ng);
  const Vector3f d = Frame(n).toWorld(warp::squareToCosineHemisphere(sampler.next2D()));
  Ray shadow = si.spawnRay(d);
  shadow.tmax = distance_;
  ++context.stats.rays;
  return scene.occluded(shadow) ? Color3::Zero() : Color3::Ones();
}

}  // namespace verity
