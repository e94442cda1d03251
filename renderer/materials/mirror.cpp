#include "materials/mirror.h"

#include "materials/sample_util.h"

namespace verity {

std::optional<BsdfSample> Mirror::sample(const TextureQuery& q, const Vector3f& wi, float,
                                         const Point2f&, TransportMode) const {
  if (wi.z() <= 0) return std::nullopt;
  BsdfSample s;
  s.wo = Vector3f(-wi.x(), -wi.y(), wi.z());
  s.weight = sanitize(albedo_.eval(q));
  s.pdf = 1.0f;
  s.lobe = kReflection | kSpecular;
  return s;
}

}  // namespace verity
