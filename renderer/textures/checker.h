// Alternates two textures in a solid 3D checkerboard of cells of size 1/scale.
#pragma once

#include "textures/texture.h"

namespace verity {

class CheckerTexture : public Texture {
 public:
  CheckerTexture(TexturedColor even, TexturedColor odd, float scale)
      : even_(std::move(even)), odd_(std::move(odd)), scale_(scale) {}
  Color3 eval(const TextureQuery& q) const override;

 private:
  TexturedColor even_, odd_;
  float scale_;
};

}  // namespace verity
