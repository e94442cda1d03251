// A bitmap looked up by uv with bilinear filtering and wrapping. 8-bit files are sRGB and
// converted to linear; Radiance .hdr and OpenEXR files are linear already.
#pragma once

#include <filesystem>
#include <vector>

#include "textures/texture.h"
#include "textures/texture_type.h"

namespace verity {

class ImageTexture : public Texture {
 public:
  // Throws VerityError naming `jsonPath` when the file cannot be read.
  ImageTexture(const std::filesystem::path& file, const std::string& jsonPath);
  Color3 eval(const TextureQuery& q) const override;
  float upperBound() const override { return upperBound_; }

  int width() const { return width_; }
  int height() const { return height_; }
  // Texel (x, y), row 0 at the top of the image.
  Color3 texel(int x, int y) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> rgb_;
  float upperBound_ = 0;  // the largest texel value
};

// The scene format's "image".
TextureType imageTextureType();

}  // namespace verity
