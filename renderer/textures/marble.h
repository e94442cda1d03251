// Marble: veins along x perturbed by Perlin turbulence (Perlin 1985, "An Image
// Synthesizer"), blending a base colour into a vein colour.
#pragma once

#include "textures/texture.h"

namespace verity {

class MarbleTexture : public Texture {
 public:
  MarbleTexture(TexturedColor veins, TexturedColor base, float scale)
      : veins_(std::move(veins)), base_(std::move(base)), scale_(scale) {}
  Color3 eval(const TextureQuery& q) const override;

 private:
  TexturedColor veins_, base_;
  float scale_;
};

}  // namespace verity
