#include "materials/material_factory.h"

#include <fmt/format.h>

#include "materials/blend.h"
#include "materials/blinn_phong.h"
#include "materials/dielectric.h"
#include "materials/diffuse_light.h"
#include "materials/lambertian.h"
#include "materials/mirror.h"
#include "materials/oren_nayar.h"
#include "materials/phong.h"
#include "materials/rough_conductor.h"
#include "materials/rough_dielectric.h"

namespace verity {

namespace {
// "sampling": how microfacet normals are sampled.
MicrofacetSampling parseSampling(const JsonNode& node) {
  auto s = node.find({"sampling"});
  if (!s) return MicrofacetSampling::Visible;
  const std::string mode = s->asString();
  if (mode == "visible") return MicrofacetSampling::Visible;
  if (mode == "normals") return MicrofacetSampling::Normals;
  s->fail("unknown sampling mode \"" + mode + "\" (expected \"visible\" or \"normals\")");
}

MicrofacetType parseDistribution(const JsonNode& node) {
  auto d = node.find({"distribution"});
  if (!d) return MicrofacetType::GGX;
  const std::string name = d->asString();
  if (name == "ggx") return MicrofacetType::GGX;
  if (name == "beckmann") return MicrofacetType::Beckmann;
  d->fail("unknown microfacet distribution \"" + name + "\" (expected \"ggx\" or \"beckmann\")");
}

// A texture-valued roughness must not be negative where it is a constant (a texture is
// clamped at lookup).
TexturedColor parseRoughness(TextureFactory& textures, const JsonNode& node) {
  TexturedColor r = textures.parse(node, {"roughness"}, Color3::Zero());
  if (r.isConstant() && !(r.constant() >= 0).all())
    node[{"roughness"}].fail("roughness must not be negative");
  return r;
}
}  // namespace

TexturedColor MaterialFactory::parseAlbedo(const JsonNode& node) {
  TexturedColor albedo = textures_.parse(node, {"albedo"}, Color3::Constant(0.8f));
  const float bound = albedo.upperBound();
  if (bound > 1)
    warnings_.push_back(node[{"albedo"}].warning(fmt::format(
        "{} {:g}, above 1: the surface reflects more light than reaches it (a white furnace "
        "would gain energy)",
        albedo.isConstant() ? "an albedo of" : "a texture that reaches", bound)));
  return albedo;
}

std::shared_ptr<const Material> MaterialFactory::make(const JsonNode& node) {
  const std::string type = node.type();
  node.find({"name"});  // the name is read by the scene loader
  std::shared_ptr<const Material> material;
  if (type == "lambertian") {
    material = std::make_shared<Lambertian>(parseAlbedo(node));
  } else if (type == "diffuse light" || type == "diffuse_light") {
    const Color3 emit = node.getVector3({"emit"}, Vector3f::Ones()).array();
    if (!(emit >= 0).all()) node[{"emit"}].fail("emitted radiance must not be negative");
    if ((emit == 0).all())
      warnings_.push_back(node.warning("a diffuse light whose emit is 0 emits nothing"));
    material = std::make_shared<DiffuseLight>(emit);
  } else if (type == "metal") {
    TexturedColor albedo = parseAlbedo(node);
    TexturedColor roughness = parseRoughness(textures_, node);
    if (roughness.isConstant() && roughness.constant().mean() == 0) {
      material = std::make_shared<Mirror>(std::move(albedo));
    } else {
      RoughConductor::Params p;
      p.distribution = MicrofacetType::GGX;
      p.sampling = parseSampling(node);
      p.albedo = std::move(albedo);
      p.roughness = std::move(roughness);
      p.squareRoughness = true;
      p.fresnel = RoughConductor::FresnelModel::Schlick;
      material = std::make_shared<RoughConductor>(std::move(p));
    }
  } else if (type == "dielectric") {
    material = std::make_shared<Dielectric>(node.getFloat({"ior"}, 1.5f, Range::positive()));
  } else if (type == "phong" || type == "blinnphong" || type == "blinn_phong" ||
             type == "blinn-phong") {
    TexturedColor albedo = parseAlbedo(node);
    const float exponent = node.getFloat({"exponent"}, 10.0f, Range{0.0f, 1e6f});
    if (type == "phong")
      material = std::make_shared<Phong>(std::move(albedo), exponent);
    else
      material = std::make_shared<BlinnPhong>(std::move(albedo), exponent);
  } else if (type == "beckmann" || type == "ggx") {
    RoughConductor::Params p;
    p.distribution = type == "ggx" ? MicrofacetType::GGX : MicrofacetType::Beckmann;
    p.sampling = parseSampling(node);
    p.albedo = parseAlbedo(node);
    p.roughness =
        TexturedColor(Color3::Constant(node.getFloat({"ab", "alpha"}, 0.5f, Range::nonNegative())));
    p.eta = Color3::Constant(node.getFloat({"ior"}, 0.05f, Range::positive()));
    p.k = Color3::Constant(node.getFloat({"ext"}, 3.9f, Range::nonNegative()));
    material = std::make_shared<RoughConductor>(std::move(p));
  } else if (type == "rough_dielectric" || type == "rough dielectric" ||
             type == "roughdielectric") {
    const MicrofacetType distribution = parseDistribution(node);
    const float alpha = node.getFloat({"alpha", "ab"}, 0.1f, Range::nonNegative());
    const float ior = node.getFloat({"ior"}, 1.5f, Range::positive());
    material = std::make_shared<RoughDielectric>(distribution, alpha, ior, parseSampling(node));
  } else if (type == "oren-nayar" || type == "oren_nayar") {
    TexturedColor albedo = parseAlbedo(node);
    const float sigma = node.getFloat({"sigma"}, 0.35f, Range::nonNegative());
    material = std::make_shared<OrenNayar>(std::move(albedo), sigma);
  } else if (type == "blend") {
    auto a = reference(node[{"a"}]);
    auto b = reference(node[{"b"}]);
    TexturedColor amount = textures_.parse(node, {"amount"}, Color3::Constant(0.5f));
    if (amount.isConstant() && !(amount.constant() <= 1).all())
      node[{"amount"}].fail("the blend amount must lie in [0, 1]");
    material = std::make_shared<Blend>(std::move(a), std::move(b), std::move(amount));
  } else {
    node[{"type"}].fail("unknown material type \"" + type + "\"");
  }
  node.rejectUnknownKeys();
  return material;
}

void MaterialFactory::addNamed(const JsonNode& nameNode, std::shared_ptr<const Material> material) {
  const std::string name = nameNode.asString();
  if (!named_.emplace(name, std::move(material)).second)
    nameNode.fail("a material named \"" + name + "\" is already defined");
}

std::shared_ptr<const Material> MaterialFactory::reference(const JsonNode& node) {
  if (node.isString()) {
    const std::string name = node.asString();
    auto it = named_.find(name);
    if (it == named_.end()) node.fail("no material is named \"" + name + "\"");
    return it->second;
  }
  if (!node.isObject()) node.fail("expected a material name or a material object");
  return make(node);
}

}  // namespace verity
