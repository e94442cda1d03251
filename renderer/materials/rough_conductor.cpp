#include "materials/rough_conductor.h"

#include "materials/fresnel.h"
#include "materials/sample_util.h"

namespace verity {

MicrofacetDistribution RoughConductor::distribution(const TextureQuery& q) const {
  const float r = std::max(p_.roughness.evalScalar(q), 0.0f);
  return MicrofacetDistribution(p_.distribution, p_.squareRoughness ? r * r : r, p_.sampling);
}

Color3 RoughConductor::eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                            TransportMode) const {
  if (wi.z() <= 0 || wo.z() <= 0) return Color3::Zero();
  const Vector3f sum = wi + wo;
  if (sum.squaredNorm() == 0) return Color3::Zero();
  const Vector3f h = sum.normalized();
  const MicrofacetDistribution dist = distribution(q);
  const float cosD = std::max(wi.dot(h), 0.0f);
  const Color3 fresnel = p_.fresnel == FresnelModel::Complex
                             ? fresnelConductor(cosD, p_.eta, p_.k)
                             : fresnelSchlick(cosD, p_.albedo.eval(q));
  const Color3 tint = p_.fresnel == FresnelModel::Complex ? p_.albedo.eval(q) : Color3::Ones();
  const float value = dist.D(h) * dist.G2(wi, wo, h) / (4.0f * wi.z() * wo.z());
  return sanitize(tint * fresnel * value);
}

float RoughConductor::pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const {
  if (wi.z() <= 0 || wo.z() <= 0) return 0;
  const Vector3f sum = wi + wo;
  if (sum.squaredNorm() == 0) return 0;
  const Vector3f h = sum.normalized();
  // Reflection Jacobian dωh/dωo = 1/(4 wo·h) (Walter et al. 2007, eq. 14). wo·h = wi·h
  // exactly, but not in floating point near grazing angles, where h is poorly determined:
  // reading wi·h, as the visible-normal density does, makes that factor cancel exactly in
  // the sample weight, which then stays F·G2/G1 <= 1.
  const float cosI = wi.dot(h);
  if (!(cosI > 0)) return 0;
  return sanitize(distribution(q).pdfNormal(wi, h) / (4.0f * cosI));
}

std::optional<BsdfSample> RoughConductor::sample(const TextureQuery& q, const Vector3f& wi, float,
                                                 const Point2f& u, TransportMode mode) const {
  if (wi.z() <= 0) return std::nullopt;
  const Vector3f m = distribution(q).sampleNormal(wi, u);
  if (wi.dot(m) <= 0) return std::nullopt;
  const Vector3f wo = reflect(wi, m).normalized();
  if (wo.z() <= 0) return std::nullopt;  // reflected below the horizon: an invalid sample
  // Value and density from (wi, wo) alone, so that the sample agrees with eval() and pdf().
  return makeSample(wo, eval(q, wi, wo, mode), pdf(q, wi, wo), kReflection | kGlossy);
}

}  // namespace verity
