#include "textures/marble.h"

#include <stb_perlin.h>

namespace verity {

Color3 MarbleTexture::eval(const TextureQuery& q) const {
  const Vector3f s = mapping_(q.p) * scale_;
  // The noise repeats every 256 units (stb_perlin's lattice), and fmod is exact, so wrapping
  // changes no value and keeps the lattice's integer conversions in range.
  const Vector3f n = s.unaryExpr([](float v) { return std::fmod(v, 256.0f); });
  const float turbulence = stb_perlin_turbulence_noise3(n.x(), n.y(), n.z(), 2.0f, 0.5f, 6);
  const float t = 0.5f * (1 + std::sin(s.x() + 10 * turbulence));
  return (1 - t) * veins_.eval(q) + t * base_.eval(q);
}

}  // namespace verity
