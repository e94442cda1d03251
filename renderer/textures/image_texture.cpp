#include "textures/image_texture.h"

#include <stb_image.h>

#include "core/error.h"

namespace verity {

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float v) {
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

ImageTexture::ImageTexture(const std::filesystem::path& file, const std::string& jsonPath) {
  int channels = 0;
  const std::string name = file.string();
  if (!std::filesystem::is_regular_file(file))
    throw VerityError("", jsonPath, "image file \"" + name + "\" does not exist");
  if (stbi_is_hdr(name.c_str())) {
    float* data = stbi_loadf(name.c_str(), &width_, &height_, &channels, 3);
    if (!data)
      throw VerityError("", jsonPath,
                        "cannot decode image \"" + name + "\": " + stbi_failure_reason());
    rgb_.assign(data, data + size_t(width_) * height_ * 3);
    stbi_image_free(data);
  } else {
    unsigned char* data = stbi_load(name.c_str(), &width_, &height_, &channels, 3);
    if (!data)
      throw VerityError("", jsonPath,
                        "cannot decode image \"" + name + "\": " + stbi_failure_reason());
    float table[256];
    for (int i = 0; i < 256; ++i) table[i] = srgbToLinear(i / 255.0f);
    rgb_.resize(size_t(width_) * height_ * 3);
    for (size_t i = 0; i < rgb_.size(); ++i) rgb_[i] = table[data[i]];
    stbi_image_free(data);
  }
  for (float v : rgb_) upperBound_ = std::max(upperBound_, v);
}

namespace {
// x − ⌊x⌋, and 0 for a non-finite x.
float wrapUnit(float x) {
  const float f = x - std::floor(x);
  return std::isfinite(f) ? f : 0.0f;
}
}  // namespace

Color3 ImageTexture::texel(int x, int y) const {
  x = ((x % width_) + width_) % width_;
  y = ((y % height_) + height_) % height_;
  const float* p = &rgb_[(size_t(y) * width_ + x) * 3];
  return {p[0], p[1], p[2]};
}

Color3 ImageTexture::eval(const TextureQuery& q) const {
  // The image repeats: uv is wrapped into [0, 1) first, so that any finite uv, however large,
  // gives texel indices in range. v = 0 is the bottom row of the image.
  const float x = wrapUnit(q.uv.x()) * width_ - 0.5f;
  const float y = (1 - wrapUnit(q.uv.y())) * height_ - 0.5f;
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - x0, fy = y - y0;
  return (1 - fx) * (1 - fy) * texel(x0, y0) + fx * (1 - fy) * texel(x0 + 1, y0) +
         (1 - fx) * fy * texel(x0, y0 + 1) + fx * fy * texel(x0 + 1, y0 + 1);
}

}  // namespace verity
