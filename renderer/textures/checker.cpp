#include "textures/checker.h"

namespace verity {

Color3 CheckerTexture::eval(const TextureQuery& q) const {
  // A solid checkerboard in world space, cells of size 1/scale.
  const Vector3f s = q.p * scale_;
  const long parity = static_cast<long>(std::floor(s.x())) + static_cast<long>(std::floor(s.y())) +
                      static_cast<long>(std::floor(s.z()));
  return (parity & 1) ? odd_.eval(q) : even_.eval(q);
}

}  // namespace verity
