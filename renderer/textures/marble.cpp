#include "textures/marble.h"

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

const Key<TexturedColor> kVeins{.name = "veins",
                                .defaultValue = TexturedColor(Color3::Constant(0.1f)),
                                .allowed = "each channel >= 0",
                                .meaning = "the colour of the veins"};
const Key<TexturedColor> kBase{.name = "base",
                               .defaultValue = TexturedColor(Color3::Constant(0.9f)),
                               .allowed = "each channel >= 0",
                               .meaning = "the colour between the veins"};
const Key<float> kMarbleScale{
    .name = "scale",
    .defaultValue = 1,
    .allowed = {0.0f, kMaxScale, true, false},
    .meaning = "the pattern's frequency: veins repeat every 2π/scale along x"};
}  // namespace

TextureType marbleTextureType() {
  return {"marble",
          {},
          "solid marble: veins running across x, bent by Perlin turbulence",
          declarations(kVeins, kBase, kMarbleScale, solidTransformKey()),
          [](const JsonNode& node, TextureFactory& factory, const std::string& quantity) {
            TexturedColor veins = factory.parse(node, kVeins, quantity);
            TexturedColor base = factory.parse(node, kBase, quantity);
            const float scale = node.get(kMarbleScale);
            return TexturedColor(
                std::make_shared<MarbleTexture>(veins, base, scale, parseSolidMapping(node)));
          }};
}

}  // namespace verity
