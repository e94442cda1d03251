// A rough dielectric interface, reflection and transmission (Walter et al. 2007,
// "Microfacet Models for Refraction through Rough Surfaces"), with a Beckmann or GGX
// distribution and height-correlated Smith masking-shadowing (Heitz 2014). `ior` is the
// interior index over the exterior one; wi.z < 0 means wi is inside.
//
// Transmission, with ηi, ηo the indices on wi's and wo's sides and
// h = ±normalize(ηi·wi + ηo·wo) (Walter eq. 16):
//   f(wi, wo) = |wi·h||wo·h| / (|cos θi||cos θo|) · η² (1 − F) G2 D / (ηi wi·h + ηo wo·h)²
// with η² = ηi² in TransportMode::Radiance (Walter eq. 21 with light arriving along wo)
// and ηo² for importance. Hence generalised reciprocity, in radiance mode:
// f(wi, wo) / ηi² = f(wo, wi) / ηo², and the importance-mode f is the radiance-mode f
// with its arguments swapped. An index-matched interface (|ior − 1| <= 1e-3, so 1.001 and
// 1/1.001 included, 1.002 and 1/1.002 not) is treated as smooth: its refraction lobe is
// narrower than 1e-3 rad and its half-vector formulas lose all precision as ior → 1. There
// sample() draws only delta lobes (Fresnel reflection or straight pass-through, as the
// smooth dielectric does) and eval() and pdf() are 0: a chi-square test of it has no valid
// sample and is INCONCLUSIVE, never PASSED (chi2/suite/tests/degenerate_test.cpp).
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"
#include "materials/microfacet.h"

namespace verity {

class RoughDielectric : public Material {
 public:
  RoughDielectric(MicrofacetType distribution, float alpha, float ior, MicrofacetSampling sampling);

  Color3 eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
              TransportMode mode) const override;
  float pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const override;
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override;
  uint32_t lobes() const override {
    return kReflection | kTransmission | (indexMatched_ ? kSpecular : kGlossy);
  }
  float interiorIndex() const override { return ior_; }
  bool isTextured() const override { return false; }

 private:
  // The generalised half vector of (wi, wo), oriented to +z, with the indices of both
  // sides; false when the pair cannot come from one microfacet.
  // In double precision, from directions renormalised there (unitDouble, sample_util.h).
  struct Geometry {
    Eigen::Vector3d wi, wo, h;
    double etaI, etaO;
    bool reflection;
    double fresnel;  // fresnelOf the configuration, read by both value and density
  };
  // False where eval() and pdf() are zero (index-matched, on the horizon, or no microfacet
  // joins wi and wo).
  bool geometry(const Vector3f& wi, const Vector3f& wo, Geometry& g) const;
  // eval() and pdf() of a configuration, which sample() computes once for both.
  float value(const Geometry& g, TransportMode mode) const;
  float density(const Geometry& g) const;

  MicrofacetDistribution dist_;
  float ior_;
  bool indexMatched_;
};

// "rough_dielectric" in the scene format (material_registry.h).
MaterialType roughDielectricType();

}  // namespace verity
