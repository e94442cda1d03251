#include "materials/rough_dielectric.h"

#include "materials/dielectric.h"
#include "materials/fresnel.h"
#include "materials/material_factory.h"
#include "materials/material_keys.h"
#include "materials/sample_util.h"

namespace verity {

RoughDielectric::RoughDielectric(MicrofacetType distribution, float alpha, float ior,
                                 MicrofacetSampling sampling)
    : dist_(distribution, alpha, sampling),
      ior_(ior),
      indexMatched_(std::abs(ior - 1.0f) <= 1e-3f) {}

namespace {
// Fresnel reflectance of a configuration. Across a transmission both directions satisfy
// Snell's law about h, so F may be read from either side; reading it from the side of the
// lower index (never near total internal reflection, where F is ill-conditioned) makes
// f(wi, wo) and f(wo, wi) use the very same value. In a reflection wi·h = wo·h up to
// rounding, which near the critical angle (where dF/dcos is unbounded) shows as a 0.1%
// asymmetry; their mean is symmetric by construction.
float fresnelOf(const Vector3f& wi, const Vector3f& wo, const Vector3f& h, float ior,
                bool reflection) {
  if (reflection) return fresnelDielectric(0.5f * (wi.dot(h) + wo.dot(h)), ior);
  const bool wiOnLowSide = (wi.z() > 0) == (ior >= 1);
  return fresnelDielectric(wiOnLowSide ? wi.dot(h) : wo.dot(h), ior);
}
}  // namespace

bool RoughDielectric::geometry(const Vector3f& wi, const Vector3f& wo, Geometry& g) const {
  if (wi.z() == 0 || wo.z() == 0) return false;
  g.reflection = wi.z() * wo.z() > 0;
  g.etaI = wi.z() > 0 ? 1.0f : ior_;
  g.etaO = wo.z() > 0 ? 1.0f : ior_;
  const Vector3f h = g.reflection ? Vector3f(wi + wo) : Vector3f(g.etaI * wi + g.etaO * wo);
  const float len = h.norm();
  if (!(len > 0) || !std::isfinite(len)) return false;
  g.h = h / len;
  if (g.h.z() < 0) g.h = -g.h;
  if (!(g.h.z() > 0)) return false;
  // Each direction must lie on its own side of the microfacet too.
  return wi.dot(g.h) * wi.z() > 0 && wo.dot(g.h) * wo.z() > 0;
}

Color3 RoughDielectric::eval(const TextureQuery&, const Vector3f& wi, const Vector3f& wo,
                             TransportMode mode) const {
  if (indexMatched_) return Color3::Zero();
  Geometry g;
  if (!geometry(wi, wo, g)) return Color3::Zero();
  const float cosI = wi.dot(g.h), cosO = wo.dot(g.h);
  const float fresnel = fresnelOf(wi, wo, g.h, ior_, g.reflection);
  const float dg = dist_.D(g.h) * dist_.G2(wi, wo, g.h);
  float value;
  if (g.reflection) {
    value = fresnel * dg / (4.0f * std::abs(wi.z() * wo.z()));
  } else {
    const float denom = g.etaI * cosI + g.etaO * cosO;
    const float eta2 = mode == TransportMode::Radiance ? g.etaI * g.etaI : g.etaO * g.etaO;
    value = eta2 * (1.0f - fresnel) * dg * std::abs(cosI * cosO) /
            (std::abs(wi.z() * wo.z()) * denom * denom);
  }
  return Color3::Constant(sanitize(value));
}

float RoughDielectric::pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const {
  if (indexMatched_) return 0;
  Geometry g;
  if (!geometry(wi, wo, g)) return 0;
  const float cosI = wi.dot(g.h), cosO = wo.dot(g.h);
  // Normals are sampled as seen from wi's side, flipped to the upper hemisphere.
  const Vector3f wiUp = wi.z() > 0 ? wi : Vector3f(-wi);
  const float pdfM = dist_.pdfNormal(wiUp, g.h);
  const float fresnel = fresnelOf(wi, wo, g.h, ior_, g.reflection);
  float pdf;
  if (g.reflection) {
    // 1/(4 |wo·h|), read as 1/(4 |wi·h|): equal, but the latter cancels exactly against the
    // visible-normal density (see RoughConductor::pdf).
    pdf = fresnel * pdfM / (4.0f * std::abs(cosI));
  } else {
    // Refraction Jacobian dωh/dωo = ηo² |wo·h| / (ηi wi·h + ηo wo·h)² (Walter eq. 17).
    const float denom = g.etaI * cosI + g.etaO * cosO;
    pdf = (1.0f - fresnel) * pdfM * g.etaO * g.etaO * std::abs(cosO) / (denom * denom);
  }
  return sanitize(pdf);
}

std::optional<BsdfSample> RoughDielectric::sample(const TextureQuery& q, const Vector3f& wi,
                                                  float uLobe, const Point2f& u,
                                                  TransportMode mode) const {
  if (indexMatched_) return sampleSmoothDielectric(wi, ior_, uLobe, mode);
  if (wi.z() == 0) return std::nullopt;
  const Vector3f wiUp = wi.z() > 0 ? wi : Vector3f(-wi);
  const Vector3f mUp = dist_.sampleNormal(wiUp, u);
  // The microfacet normal on wi's side.
  const Vector3f m = wi.z() > 0 ? mUp : Vector3f(-mUp);
  const float cosI = wi.dot(m);
  if (cosI <= 0) return std::nullopt;  // a back-facing microfacet ("normals" sampling)
  const float fresnel = fresnelDielectric(cosI, wi.z() > 0 ? ior_ : 1.0f / ior_);
  Vector3f wo;
  uint32_t lobe;
  float eta = 1.0f;
  if (uLobe < fresnel) {
    wo = reflect(wi, m).normalized();
    if (wo.z() * wi.z() <= 0) return std::nullopt;
    lobe = kReflection | kGlossy;
  } else {
    eta = wi.z() > 0 ? ior_ : 1.0f / ior_;
    if (!refract(wi, m, eta, wo)) return std::nullopt;
    if (wo.z() * wi.z() >= 0) return std::nullopt;
    lobe = kTransmission | kGlossy;
  }
  // Value and density from (wi, wo) alone, so that the sample agrees with eval() and pdf().
  return makeSample(wo, eval(q, wi, wo, mode), pdf(q, wi, wo), lobe, eta);
}

namespace {

const Key<float> kRoughDielectricAlpha = alphaKey("alpha", "ab", 0.1f);

}  // namespace

MaterialType roughDielectricType() {
  return {"rough_dielectric",
          {"rough dielectric", "roughdielectric"},
          "rough glass (Walter et al. 2007)",
          declarations(kDistribution, kRoughDielectricAlpha, kIor, kSampling),
          [](MaterialFactory&, const JsonNode& node) -> std::shared_ptr<const Material> {
            return std::make_shared<RoughDielectric>(node.get(kDistribution),
                                                     node.get(kRoughDielectricAlpha),
                                                     node.get(kIor), node.get(kSampling));
          }};
}

}  // namespace verity
