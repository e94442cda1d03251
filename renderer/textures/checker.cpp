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

TextureType checkerTextureType() {
  return {"checker",
          "a solid checkerboard of cubic cells alternating two textures",
          {{"even",
            {},
            ValueType::Texture,
            "each channel >= 0",
            "1",
            "the cells whose integer coordinates ⌊scale · p⌋ sum to an even number"},
           {"odd", {}, ValueType::Texture, "each channel >= 0", "0", "the other cells"},
           {"scale",
            {},
            ValueType::Number,
            "> 0",
            "1",
            "cells per unit length: a cell's side is 1/scale"},
           solidTransformKey()},
          [](const JsonNode& node, TextureFactory& factory, const std::string& quantity) {
            TexturedColor even = factory.parse(node, {"even"}, Color3::Ones(), quantity);
            TexturedColor odd = factory.parse(node, {"odd"}, Color3::Zero(), quantity);
            const float scale = node.getFloat({"scale"}, 1.0f, Range::positive());
            return TexturedColor(
                std::make_shared<CheckerTexture>(even, odd, scale, parseSolidMapping(node)));
          }};
}

}  // namespace verity
