// Alternates two textures in a solid 3D checkerboard of cells of size 1/scale.
#pragma once

#include "textures/solid_mapping.h"
#include "textures/texture.h"
#include "textures/texture_type.h"

namespace verity {

class CheckerTexture : public Texture {
 public:
  CheckerTexture(TexturedColor even, TexturedColor odd, float scale, SolidMapping mapping = {})
      : even_(std::move(even)), odd_(std::move(odd)), scale_(scale), mapping_(mapping) {}
  Color3 eval(const TextureQuery& q) const override;
  float upperBound() const override { return std::max(even_.upperBound(), odd_.upperBound()); }

 private:
  TexturedColor even_, odd_;
  float scale_;
  SolidMapping mapping_;
};

// The scene format's "checker".
TextureType checkerTextureType();

}  // namespace verity
