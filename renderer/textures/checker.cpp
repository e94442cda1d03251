#include "textures/checker.h"

#include "params/json_node.h"
#include "textures/texture_factory.h"

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

namespace {

const Key<TexturedColor> kEven{
    .name = "even",
    .defaultValue = TexturedColor(Color3::Ones()),
    .allowed = "each channel >= 0",
    .meaning = "the cells whose integer coordinates ⌊scale · p⌋ sum to an even number"};
const Key<TexturedColor> kOdd{.name = "odd",
                              .defaultValue = TexturedColor(Color3::Zero()),
                              .allowed = "each channel >= 0",
                              .meaning = "the other cells"};
const Key<float> kCheckerScale{.name = "scale",
                               .defaultValue = 1,
                               .allowed = Range::positive(),
                               .meaning = "cells per unit length: a cell's side is 1/scale"};

}  // namespace

TextureType checkerTextureType() {
  return {"checker",
          {},
          "a solid checkerboard of cubic cells alternating two textures",
          declarations(kEven, kOdd, kCheckerScale, solidTransformKey()),
          [](const JsonNode& node, TextureFactory& factory, const std::string& quantity) {
            TexturedColor even = factory.parse(node, kEven, quantity);
            TexturedColor odd = factory.parse(node, kOdd, quantity);
            const float scale = node.get(kCheckerScale);
            return TexturedColor(
                std::make_shared<CheckerTexture>(even, odd, scale, parseSolidMapping(node)));
          }};
}

}  // namespace verity
