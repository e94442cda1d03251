#include "textures/image_texture.h"

#include <ImfTestFile.h>
#include <fmt/format.h>
#include <stb_image.h>

#include <cmath>

#include "core/error.h"
#include "film/image_io.h"
#include "film/srgb.h"
#include "params/json_node.h"
#include "textures/texture_factory.h"

namespace verity {

namespace {
// The R, G and B planes of an OpenEXR file, interleaved. Its values must be finite and not
// negative, as a constant colour's must.
std::vector<float> readExrRgb(const std::filesystem::path& file, const std::string& jsonPath,
                              int* width, int* height) {
  const std::string name = file.string();
  ImageChannels image;
  try {
    image = readExr(file);
  } catch (const VerityError& e) {
    throw VerityError("", jsonPath, "\"" + name + "\": " + e.problem());
  }
  const char* names[3] = {"R", "G", "B"};
  for (const char* c : names)
    if (!image.planes.count(c))
      throw VerityError("", jsonPath,
                        "the OpenEXR image \"" + name + "\" has no " + c +
                            " channel (a texture needs R, G and B)");
  *width = image.width;
  *height = image.height;
  std::vector<float> rgb(size_t(image.width) * image.height * 3);
  for (int c = 0; c < 3; ++c) {
    const std::vector<float>& plane = image.planes.at(names[c]);
    for (size_t i = 0; i < plane.size(); ++i) {
      if (!(plane[i] >= 0) || !std::isfinite(plane[i]))
        throw VerityError("", jsonPath,
                          fmt::format("the OpenEXR image \"{}\" holds {} in {} at pixel ({}, {}): "
                                      "a texture's values must be finite and not negative",
                                      name, plane[i], names[c], i % image.width, i / image.width));
      rgb[3 * i + c] = plane[i];
    }
  }
  return rgb;
}
}  // namespace

ImageTexture::ImageTexture(const std::filesystem::path& file, const std::string& jsonPath) {
  int channels = 0;
  const std::string name = file.string();
  if (std::filesystem::is_directory(file))
    throw VerityError("", jsonPath, "\"" + name + "\" is a directory, not an image file");
  if (!std::filesystem::is_regular_file(file))
    throw VerityError("", jsonPath, "image file \"" + name + "\" does not exist");
  if (Imf::isOpenExrFile(name.c_str())) {
    rgb_ = readExrRgb(file, jsonPath, &width_, &height_);
  } else if (stbi_is_hdr(name.c_str())) {
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

namespace {

const Key<std::string> kImageFile{
    .name = "filename",
    .allowed = "a PNG, JPEG, BMP, TGA, Radiance .hdr or OpenEXR file, relative to the scene file",
    .meaning =
        "the image: 8-bit files are sRGB, .hdr and OpenEXR linear; (u, v) = (0, 0) is its "
        "bottom-left corner"};

}  // namespace

TextureType imageTextureType() {
  return {"image",
          {},
          "a bitmap looked up by the surface's uv, bilinearly filtered and repeated",
          declarations(kImageFile),
          [](const JsonNode& node, TextureFactory& factory, const std::string&) {
            return TexturedColor(factory.image(node[kImageFile]));
          }};
}

}  // namespace verity
