// A rough conductor (Cook-Torrance with Walter et al. 2007's normalisation):
// f = tint·F(wi·h)·D(h)·G2(wi, wo, h) / (4 cos θi cos θo), with a Beckmann or GGX
// distribution and height-correlated Smith masking-shadowing.
//
// Two parameterisations share it:
//  - DIRT's "beckmann" and the seed's "ggx": alpha given directly ("ab"), Fresnel of the
//    complex index ior + i·ext, multiplied by the albedo texture as a tint. "ior" and
//    "ext" are each a number or an RGB triple [r, g, b] (one index per channel); or
//    "conductor" names a measured metal instead ("Au", "Ag", "Cu", "Al";
//    named_conductors.h), and then neither may be given.
//  - DIRT's "metal" with roughness r > 0: GGX with α = r² (the perceptual remapping of
//    Burley 2012, "Physically-Based Shading at Disney"), Schlick's Fresnel with F0 = albedo,
//    so that albedo is the colour at normal incidence as for the r = 0 mirror.
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"
#include "materials/microfacet.h"

namespace verity {

class RoughConductor : public Material {
 public:
  enum class FresnelModel { Complex, Schlick };
  struct Params {
    MicrofacetType distribution = MicrofacetType::GGX;
    MicrofacetSampling sampling = MicrofacetSampling::Visible;
    TexturedColor albedo{Color3::Constant(0.8f)};
    // Roughness texture (its channel mean is read); α = roughness, or roughness² when
    // squareRoughness.
    TexturedColor roughness{Color3::Constant(0.5f)};
    bool squareRoughness = false;
    FresnelModel fresnel = FresnelModel::Complex;
    Color3 eta = Color3::Constant(0.05f);
    Color3 k = Color3::Constant(3.9f);
  };

  explicit RoughConductor(Params params);

  Color3 eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
              TransportMode mode) const override;
  float pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const override;
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override;
  uint32_t lobes() const override { return kReflection | kGlossy; }
  bool isTextured() const override { return !p_.albedo.isConstant() || !p_.roughness.isConstant(); }

 private:
  // wi, wo and their half vector in double precision; none below the horizon.
  struct HalfVector {
    Eigen::Vector3d i, o, h;
    double halfLength;  // |wi + wo|/2 = wi·h, without the dot product's cancellation
  };
  static std::optional<HalfVector> halfVector(const Vector3f& wi, const Vector3f& wo);
  // eval() and pdf() at a half vector, which sample() computes once for both.
  Color3 value(const TextureQuery& q, const MicrofacetDistribution& dist,
               const HalfVector& g) const;
  static float density(const MicrofacetDistribution& dist, const HalfVector& g);
  MicrofacetDistribution distribution(const TextureQuery& q) const;
  // The distribution for a roughness texture's value r.
  MicrofacetDistribution distributionOf(float r) const;
  Params p_;
  // An untextured roughness's distribution, built once: eval, pdf and sample each ask for it.
  std::optional<MicrofacetDistribution> constantDistribution_;
};

// "beckmann", "ggx" and "metal" in the scene format (material_registry.h); "metal" with
// roughness 0 builds a Mirror.
MaterialType beckmannType();
MaterialType ggxType();
MaterialType metalType();

}  // namespace verity
