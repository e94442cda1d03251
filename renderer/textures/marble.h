// Marble: veins along x perturbed by Perlin turbulence (Perlin 1985, "An Image
// Synthesizer"), blending a base colour into a vein colour.
#pragma once

#include "textures/solid_mapping.h"
#include "textures/texture.h"
#include "textures/texture_type.h"

namespace verity {

class MarbleTexture : public Texture {
 public:
  MarbleTexture(TexturedColor veins, TexturedColor base, float scale, SolidMapping mapping = {})
      : veins_(std::move(veins)), base_(std::move(base)), scale_(scale), mapping_(mapping) {}
  Color3 eval(const TextureQuery& q) const override;
  float upperBound() const override { return std::max(veins_.upperBound(), base_.upperBound()); }

 private:
  TexturedColor veins_, base_;
  float scale_;
  SolidMapping mapping_;
};

// The scene format's "marble".
TextureType marbleTextureType();

}  // namespace verity
