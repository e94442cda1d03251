// Ideal diffuse reflection: f = albedo / π, sampled by the cosine-weighted hemisphere.
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"

namespace verity {

class Lambertian : public Material {
 public:
  explicit Lambertian(TexturedColor albedo) : albedo_(std::move(albedo)) {}

  Color3 eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
              TransportMode mode) const override;
  float pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const override;
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override;
  uint32_t lobes() const override { return kReflection | kDiffuse; }
  bool isTextured() const override { return !albedo_.isConstant(); }

 private:
  TexturedColor albedo_;
};

// "lambertian" in the scene format (material_registry.h).
MaterialType lambertianType();

}  // namespace verity
