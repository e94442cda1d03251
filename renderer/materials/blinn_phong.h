// A normalised Blinn-Phong BRDF: f = albedo·(n+2)/(8π)·cos^n θh, θh the angle between the
// half vector and the normal (the normalisation of Akenine-Möller et al., "Real-Time
// Rendering", §7.6, without Fresnel and masking). Its albedo at normal incidence is
// n/(n+4) < 1 for albedo 1. Sampled through the half vector, density (n+1)/(2π)·cos^n θh
// per solid angle of h, mapped to wo by the 1/(4 wo·h) reflection Jacobian.
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"

namespace verity {

class BlinnPhong : public Material {
 public:
  BlinnPhong(TexturedColor albedo, float exponent)
      : albedo_(std::move(albedo)), exponent_(exponent) {}

  Color3 eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
              TransportMode mode) const override;
  float pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const override;
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override;
  uint32_t lobes() const override { return kReflection | kGlossy; }
  bool isTextured() const override { return !albedo_.isConstant(); }

 private:
  TexturedColor albedo_;
  float exponent_;
};

// "blinnphong" in the scene format (material_registry.h).
MaterialType blinnPhongType();

}  // namespace verity
