#include "core/ray.h"

#include <bit>

namespace verity {

namespace {
constexpr float kOrigin = 1.0f / 32.0f;
constexpr float kFloatScale = 1.0f / 65536.0f;
constexpr float kIntScale = 256.0f;

float offsetComponent(float p, float n, float sceneScale) {
  if (std::fabs(p) < kOrigin * sceneScale) return p + kFloatScale * sceneScale * n;
  const int of = static_cast<int>(kIntScale * n);
  const int bits = std::bit_cast<int>(p);
  return std::bit_cast<float>(bits + ((p < 0) ? -of : of));
}
}  // namespace

Point3f offsetRayOrigin(const Point3f& p, const Normal3f& n, float sceneScale) {
  return {offsetComponent(p.x(), n.x(), sceneScale), offsetComponent(p.y(), n.y(), sceneScale),
          offsetComponent(p.z(), n.z(), sceneScale)};
}

Ray spawnRay(const Point3f& p, const Normal3f& ng, const Vector3f& d, float sceneScale) {
  const Normal3f side = ng.dot(d) >= 0 ? ng : Normal3f(-ng);
  return Ray(offsetRayOrigin(p, side, sceneScale), d);
}

Ray spawnRayTo(const Point3f& p, const Normal3f& ng, const Point3f& target,
               const Normal3f& ngTarget, float sceneScale) {
  const Vector3f toTarget = target - p;
  const Point3f from = offsetRayOrigin(p, ng.dot(toTarget) >= 0 ? ng : Normal3f(-ng), sceneScale);
  const Point3f to = offsetRayOrigin(
      target, ngTarget.dot(toTarget) <= 0 ? ngTarget : Normal3f(-ngTarget), sceneScale);
  Ray ray(from, to - from, 1.0f - 1e-4f);
  return ray;
}

}  // namespace verity
