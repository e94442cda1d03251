// The normalised modified Phong BRDF (Lafortune and Willems 1994, "Using the Modified
// Phong Reflectance Model for Physically Based Rendering"): f = albedo·(n+2)/(2π)·cos^n α,
// α the angle between wo and the mirror direction of wi. The (n+2)/(2π) factor makes the
// albedo exactly `albedo` at normal incidence and less elsewhere; the lobe is symmetric in
// wi and wo. Sampled by the lobe itself, (n+1)/(2π)·cos^n α about the mirror direction.
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"

namespace verity {

class Phong : public Material {
 public:
  Phong(TexturedColor albedo, float exponent) : albedo_(std::move(albedo)), exponent_(exponent) {}

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

// "phong" in the scene format (material_registry.h).
MaterialType phongType();

}  // namespace verity
