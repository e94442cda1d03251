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
float fresnelOf(const Eigen::Vector3d& wi, const Eigen::Vector3d& wo, const Eigen::Vector3d& h,
                float ior, bool reflection) {
  if (reflection) return fresnelDielectric(float(0.5 * (wi.dot(h) + wo.dot(h))), ior);
  const bool wiOnLowSide = (wi.z() > 0) == (ior >= 1);
  return fresnelDielectric(float(wiOnLowSide ? wi.dot(h) : wo.dot(h)), ior);
}
}  // namespace

bool RoughDielectric::geometry(const Vector3f& wiF, const Vector3f& woF, Geometry& g) const {
  if (indexMatched_ || wiF.z() == 0 || woF.z() == 0) return false;
  // Double precision: at α = 1e-4 and grazing incidence the lobe is narrower than the half
  // vector read in single precision (pdf integrals of 0.9948 at 89.9°, 1.354 at 90°).
  g.wi = unitDouble(wiF);
  g.wo = unitDouble(woF);
  const Eigen::Vector3d &wi = g.wi, &wo = g.wo;
  g.reflection = wi.z() * wo.z() > 0;
  g.etaI = wi.z() > 0 ? 1.0 : ior_;
  g.etaO = wo.z() > 0 ? 1.0 : ior_;
  const Eigen::Vector3d h =
      g.reflection ? Eigen::Vector3d(wi + wo) : Eigen::Vector3d(g.etaI * wi + g.etaO * wo);
  const double len = h.norm();
  if (!(len > 0) || !std::isfinite(len)) return false;
  g.h = h * (1 / len);
  if (g.h.z() < 0) g.h = -g.h;
  if (!(g.h.z() > 0)) return false;
  // Each direction must lie on its own side of the microfacet too.
  if (!(wi.dot(g.h) * wi.z() > 0 && wo.dot(g.h) * wo.z() > 0)) return false;
  g.fresnel = fresnelOf(wi, wo, g.h, ior_, g.reflection);
  return true;
}

float RoughDielectric::value(const Geometry& g, TransportMode mode) const {
  const Eigen::Vector3d &wi = g.wi, &wo = g.wo;
  const double cosI = wi.dot(g.h), cosO = wo.dot(g.h);
  const double dg = dist_.D(g.h) * dist_.G2(wi, wo, g.h);
  double value;
  if (g.reflection) {
    value = g.fresnel * dg / (4.0 * std::abs(wi.z() * wo.z()));
  } else {
    const double denom = g.etaI * cosI + g.etaO * cosO;
    const double eta2 = mode == TransportMode::Radiance ? g.etaI * g.etaI : g.etaO * g.etaO;
    value = eta2 * (1.0 - g.fresnel) * dg * std::abs(cosI * cosO) /
            (std::abs(wi.z() * wo.z()) * denom * denom);
  }
  return sanitize(float(value));
}

float RoughDielectric::density(const Geometry& g) const {
  const Eigen::Vector3d &wi = g.wi, &wo = g.wo;
  const double cosI = wi.dot(g.h), cosO = wo.dot(g.h);
  // Normals are sampled as seen from wi's side, flipped to the upper hemisphere.
  const Eigen::Vector3d wiUp = wi.z() > 0 ? wi : Eigen::Vector3d(-wi);
  const double pdfM = dist_.pdfNormal(wiUp, g.h);
  double pdf;
  if (g.reflection) {
    // 1/(4 |wo·h|), read as 1/(4 |wi·h|): equal, but the latter cancels exactly against the
    // visible-normal density (see RoughConductor::density).
    pdf = g.fresnel * pdfM / (4.0 * std::abs(cosI));
  } else {
    // Refraction Jacobian dωh/dωo = ηo² |wo·h| / (ηi wi·h + ηo wo·h)² (Walter eq. 17).
    const double denom = g.etaI * cosI + g.etaO * cosO;
    pdf = (1.0 - g.fresnel) * pdfM * g.etaO * g.etaO * std::abs(cosO) / (denom * denom);
  }
  return sanitize(float(pdf));
}

Color3 RoughDielectric::eval(const TextureQuery&, const Vector3f& wi, const Vector3f& wo,
                             TransportMode mode) const {
  Geometry g;
  return geometry(wi, wo, g) ? Color3::Constant(value(g, mode)) : Color3::Zero();
}

float RoughDielectric::pdf(const TextureQuery&, const Vector3f& wi, const Vector3f& wo) const {
  Geometry g;
  return geometry(wi, wo, g) ? density(g) : 0.0f;
}

std::optional<BsdfSample> RoughDielectric::sample(const TextureQuery&, const Vector3f& wi,
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
  // Value and density from (wi, wo) alone, as eval() and pdf() compute them, so that the
  // sample agrees with both.
  Geometry g;
  if (!geometry(wi, wo, g)) return std::nullopt;
  return makeSample(wo, Color3::Constant(value(g, mode)), density(g), lobe, eta);
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
