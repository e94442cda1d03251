#include "materials/rough_conductor.h"

#include <fmt/format.h>

#include "materials/fresnel.h"
#include "materials/material_factory.h"
#include "materials/material_keys.h"
#include "materials/mirror.h"
#include "materials/named_conductors.h"
#include "materials/sample_util.h"

namespace verity {

RoughConductor::RoughConductor(Params params) : p_(std::move(params)) {
  if (p_.roughness.isConstant())
    constantDistribution_ = distributionOf(p_.roughness.constant().mean());
}

MicrofacetDistribution RoughConductor::distributionOf(float r) const {
  r = std::max(r, 0.0f);
  return MicrofacetDistribution(p_.distribution, p_.squareRoughness ? r * r : r, p_.sampling);
}

MicrofacetDistribution RoughConductor::distribution(const TextureQuery& q) const {
  return constantDistribution_ ? *constantDistribution_
                               : distributionOf(p_.roughness.evalScalar(q));
}

std::optional<RoughConductor::HalfVector> RoughConductor::halfVector(const Vector3f& wi,
                                                                     const Vector3f& wo) {
  if (wi.z() <= 0 || wo.z() <= 0) return std::nullopt;
  // In double precision from directions renormalised there (unitDouble): at α = 1e-4 the
  // lobe is narrower than the half vector of a grazing wi read in single precision (a pdf
  // integral of 0.9947 at 89.9°, 1.354 at 90°).
  HalfVector g;
  g.i = unitDouble(wi);
  g.o = unitDouble(wo);
  const Eigen::Vector3d sum = g.i + g.o;
  const double length = sum.norm();
  if (length == 0) return std::nullopt;
  g.h = sum * (1 / length);
  g.halfLength = 0.5 * length;
  return g;
}

Color3 RoughConductor::value(const TextureQuery& q, const MicrofacetDistribution& dist,
                             const HalfVector& g) const {
  const float cosD = float(std::max(g.i.dot(g.h), 0.0));
  const Color3 fresnel = p_.fresnel == FresnelModel::Complex
                             ? fresnelConductor(cosD, p_.eta, p_.k)
                             : fresnelSchlick(cosD, p_.albedo.eval(q));
  const Color3 tint = p_.fresnel == FresnelModel::Complex ? p_.albedo.eval(q) : Color3::Ones();
  const double value = dist.D(g.h) * dist.G2(g.i, g.o, g.h) / (4.0 * g.i.z() * g.o.z());
  return sanitize(tint * fresnel * float(value));
}

float RoughConductor::density(const MicrofacetDistribution& dist, const HalfVector& g) {
  // Reflection Jacobian dωh/dωo = 1/(4 wo·h) (Walter et al. 2007, eq. 14). wo·h = wi·h
  // exactly, but not in floating point near grazing angles, where h is poorly determined:
  // reading wi·h, as the visible-normal density does, makes that factor cancel exactly in
  // the sample weight, which then stays F·G2/G1 <= 1.
  if (dist.sampling() == MicrofacetSampling::Normals) {
    // D(m) cos θm sampling has no such factor to cancel, so wi·h must be accurate: for unit
    // wi and wo it is |wi + wo|/2. As a dot product it is (1 + wi·wo)/|wi + wo|, a
    // difference of nearly equal numbers as wo nears −wi (a grazing wi): at wi.z = 6e-17
    // (90°) it read 6e-17·h.z where the true value was ~1e-4, and pdf() returned up to 1e16
    // (a pdf integral of 2.4e8); at 89.9999° it was up to 30 times too large near the
    // horizon (a pdf integral of 0.508 for 50.0% valid samples).
    return sanitize(float(dist.pdfNormal(g.i, g.h) / (4.0 * g.halfLength)));
  }
  const double cosI = g.i.dot(g.h);
  if (!(cosI > 0)) return 0;
  return sanitize(float(dist.pdfNormal(g.i, g.h) / (4.0 * cosI)));
}

Color3 RoughConductor::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                            TransportMode) const {
  const std::optional<HalfVector> g = halfVector(wi, wo);
  return g ? value(q, distribution(q), *g) : Color3::Zero();
}

float RoughConductor::pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const {
  const std::optional<HalfVector> g = halfVector(wi, wo);
  return g ? density(distribution(q), *g) : 0.0f;
}

std::optional<BsdfSample> RoughConductor::sample(const TextureQuery& q, const Vector3f& wi, float,
                                                 const Point2f& u, TransportMode) const {
  if (wi.z() <= 0) return std::nullopt;
  const MicrofacetDistribution dist = distribution(q);
  const Vector3f m = dist.sampleNormal(wi, u);
  if (wi.dot(m) <= 0) return std::nullopt;
  const Vector3f wo = reflect(wi, m).normalized();
  // Value and density from (wi, wo) alone, as eval() and pdf() compute them, so that the
  // sample agrees with both; reflected below the horizon, an invalid sample.
  const std::optional<HalfVector> g = halfVector(wi, wo);
  if (!g) return std::nullopt;
  return makeSample(wo, value(q, dist, *g), density(dist, *g), kReflection | kGlossy);
}

namespace {

// The complex index η + iκ: "conductor", a name from named_conductors.h, or "ior" (η) and
// "ext" (κ), each a number or an RGB triple, by default 0.05 + 3.9i. Stating both a name
// and an index is an error rather than a precedence rule: one of them would be ignored.
const Key<Color3> kEta{
    .name = "ior",
    .defaultValue = Color3::Constant(0.05f),
    .allowed = kIorRange,
    .meaning = "η, the real part of the complex index of refraction; not with \"conductor\""};
const Key<Color3> kExtinction{
    .name = "ext",
    .defaultValue = Color3::Constant(3.9f),
    .allowed = kExtinctionRange,
    .meaning = "κ, the imaginary part (extinction) of the complex index; not with \"conductor\""};
// Read only when given: it replaces "ior" and "ext".
const Key<std::string> kConductor{
    .name = "conductor",
    .allowed = namedConductorList(),
    .meaning = "a measured metal's index at 650, 550 and 450 nm, instead of \"ior\" and \"ext\"",
    .defaultText = "none (ior and ext)"};
const Key<float> kConductorAlpha = alphaKey("ab", "alpha", 0.5f);

void parseConductorIndex(const JsonNode& node, RoughConductor::Params& p) {
  if (auto name = node.find(kConductor)) {
    if (node.find(kEta) || node.find(kExtinction))
      name->fail("\"conductor\" and \"ior\"/\"ext\" both give the index; keep one");
    const NamedConductor* c = findNamedConductor(name->asString());
    if (!c)
      name->fail(fmt::format("unknown conductor \"{}\" (known: {})", name->asString(),
                             namedConductorList()));
    p.eta = c->eta;
    p.k = c->k;
    return;
  }
  p.eta = node.get(kEta);
  p.k = node.get(kExtinction);
}

// DIRT's "beckmann" and the seed's "ggx": α given directly, the complex Fresnel term.
std::shared_ptr<const Material> buildComplexConductor(MicrofacetType type, MaterialFactory& f,
                                                      const JsonNode& node) {
  RoughConductor::Params p;
  p.distribution = type;
  p.sampling = node.get(kSampling);
  p.albedo = f.parseAlbedo(node);
  p.roughness = TexturedColor(Color3::Constant(node.get(kConductorAlpha)));
  parseConductorIndex(node, p);
  return std::make_shared<RoughConductor>(std::move(p));
}

// The keys of "beckmann" and "ggx".
KeyList complexConductorKeys() {
  return declarations(
      kAlbedo.described("a tint on the Fresnel reflectance: 1 for the metal as measured"),
      kConductorAlpha, kEta, kExtinction, kConductor, kSampling);
}

}  // namespace

MaterialType beckmannType() {
  return {"beckmann",
          {},
          "rough conductor, Beckmann distribution, complex Fresnel term",
          complexConductorKeys(),
          [](MaterialFactory& f, const JsonNode& node) {
            return buildComplexConductor(MicrofacetType::Beckmann, f, node);
          }};
}

MaterialType ggxType() {
  return {"ggx",
          {},
          "rough conductor, GGX distribution, complex Fresnel term",
          complexConductorKeys(),
          [](MaterialFactory& f, const JsonNode& node) {
            return buildComplexConductor(MicrofacetType::GGX, f, node);
          }};
}

namespace {

const Key<TexturedColor> kMetalRoughness{
    .name = "roughness",
    .defaultValue = TexturedColor(Color3::Zero()),
    .allowed = "0 (a mirror) or [0.01, 2]; a texture at most 2",
    .meaning = "√α: the GGX roughness is its square (the mean of the channels)"};

}  // namespace

MaterialType metalType() {
  return {"metal",
          {},
          "DIRT's metal: a mirror at roughness 0, else GGX with alpha = roughness² and Schlick's "
          "Fresnel with F0 = albedo",
          declarations(kAlbedo.described("the reflectance at normal incidence (Schlick's F0)"),
                       kMetalRoughness, kSampling),
          [](MaterialFactory& f, const JsonNode& node) -> std::shared_ptr<const Material> {
            TexturedColor albedo = f.parseAlbedo(node);
            // A negative constant is refused by the texture factory (a texture is clamped at
            // lookup).
            TexturedColor roughness = f.textures().parse(node, kMetalRoughness, "roughness");
            // α = roughness² must lie in kAlphaRange (roughness in [0.01, 2]), or be 0 (a mirror).
            if (roughness.isConstant()) {
              const Color3 r = roughness.constant();
              if (!(r == 0).all() && !(r >= 0.01f && r <= 2.0f).all())
                node[kMetalRoughness].fail(
                    "roughness must be 0 (a mirror) or in [0.01, 2] (alpha = roughness² in [1e-4, "
                    "4])");
            }
            // A texture can only be bounded above here; its values below 0.01 act as 0.01 (the
            // microfacet distribution's smallest α).
            if (!roughness.isConstant() && roughness.upperBound() > 2)
              node[kMetalRoughness].fail(fmt::format(
                  "a roughness texture that reaches {:g}, above 2 (alpha = roughness² above 4)",
                  roughness.upperBound()));
            if (roughness.isConstant() && roughness.constant().mean() == 0)
              return std::make_shared<Mirror>(std::move(albedo));
            RoughConductor::Params p;
            p.distribution = MicrofacetType::GGX;
            p.sampling = node.get(kSampling);
            p.albedo = std::move(albedo);
            p.roughness = std::move(roughness);
            p.squareRoughness = true;
            p.fresnel = RoughConductor::FresnelModel::Schlick;
            return std::make_shared<RoughConductor>(std::move(p));
          }};
}

}  // namespace verity
