#include "textures/marble.h"

#include <fmt/format.h>
#include <stb_perlin.h>

#include "core/ray.h"
#include "params/json_node.h"
#include "textures/texture_factory.h"

namespace verity {

Color3 MarbleTexture::eval(const TextureQuery& q) const {
  const Vector3f s = mapping_(q.p) * scale_;
  // The noise repeats every 256 units (stb_perlin's lattice), and fmod is exact, so wrapping
  // changes no value and keeps the lattice's integer conversions in range.
  const Vector3f n = s.unaryExpr([](float v) { return std::fmod(v, 256.0f); });
  const float turbulence = stb_perlin_turbulence_noise3(n.x(), n.y(), n.z(), 2.0f, 0.5f, 6);
  const float t = 0.5f * (1 + std::sin(s.x() + 10 * turbulence));
  return (1 - t) * veins_.eval(q) + t * base_.eval(q);
}

namespace {
// Beyond this scale a point at the largest coordinate a scene may hold overflows to infinity,
// and the veins' sine of it is NaN.
constexpr float kMaxScale = std::numeric_limits<float>::max() / kMaxSceneCoordinate;
}  // namespace

TextureType marbleTextureType() {
  return {
      "marble",
      "solid marble: veins running across x, bent by Perlin turbulence",
      {{"veins", {}, ValueType::Texture, "each channel >= 0", "0.1", "the colour of the veins"},
       {"base", {}, ValueType::Texture, "each channel >= 0", "0.9", "the colour between the veins"},
       {"scale",
        {},
        ValueType::Number,
        fmt::format("(0, {:.2g}]", kMaxScale),
        "1",
        "the pattern's frequency: veins repeat every 2π/scale along x"},
       solidTransformKey()},
      [](const JsonNode& node, TextureFactory& factory, const std::string& quantity) {
        TexturedColor veins = factory.parse(node, {"veins"}, Color3::Constant(0.1f), quantity);
        TexturedColor base = factory.parse(node, {"base"}, Color3::Constant(0.9f), quantity);
        const float scale = node.getFloat({"scale"}, 1.0f, Range{0.0f, kMaxScale, true, false});
        return TexturedColor(
            std::make_shared<MarbleTexture>(veins, base, scale, parseSolidMapping(node)));
      }};
}

}  // namespace verity
