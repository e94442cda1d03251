#include "textures/marble.h"

#include <stb_perlin.h>

namespace verity {

Color3 MarbleTexture::eval(const TextureQuery& q) const {
  const Vector3f s = mapping_(q.p) * scale_;
  const float turbulence = stb_perlin_turbulence_noise3(s.x(), s.y(), s.z(), 2.0f, 0.5f, 6);
  const float t = 0.5f * (1 + std::sin(s.x() + 10 * turbulence));
  return (1 - t) * veins_.eval(q) + t * base_.eval(q);
}

}  // namespace verity
