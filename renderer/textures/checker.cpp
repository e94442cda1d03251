#include "textures/checker.h"

namespace verity {

Color3 CheckerTexture::eval(const TextureQuery& q) const {
  // A solid checkerboard in world space, cells of size 1/scale.
  // The parity of ⌊s⌋ through fmod, so that coordinates beyond the range of an integer (or
  // infinite ones) cannot overflow a conversion.
  const Vector3f s = mapping_(q.p) * scale_;
  const auto odd = [](float v) { return std::fabs(std::fmod(std::floor(v), 2.0f)) == 1.0f; };
  const bool parity = odd(s.x()) ^ odd(s.y()) ^ odd(s.z());
  return parity ? odd_.eval(q) : even_.eval(q);
}

}  // namespace verity
