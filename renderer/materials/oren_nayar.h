// Oren and Nayar 1994, "Generalization of Lambert's Reflectance Model", the qualitative
// model (their eq. 30) as DIRT uses it: f = albedo/π·(A + B·max(0, cos(φi − φo))·sin α·tan β),
// α = max(θi, θo), β = min(θi, θo), A = 1 − σ²/(2(σ² + 0.33)), B = 0.45σ²/(σ² + 0.09).
// σ, the standard deviation of the facet slope angle, is in radians (DIRT puts its
// "sigma" straight into these formulas; its default 0.35 rad is 20°). Cosine-sampled.
// Known property of the model: it is not exactly energy conserving; at grazing incidence
// its albedo tends to albedo·(A + B/2), which exceeds albedo for σ < 0.326 rad (by at
// most 1.5%).
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"

namespace verity {

class OrenNayar : public Material {
 public:
  OrenNayar(TexturedColor albedo, float sigma);

  Color3 eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
              TransportMode mode) const override;
  float pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const override;
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override;
  uint32_t lobes() const override { return kReflection | kDiffuse; }
  bool isTextured() const override { return !albedo_.isConstant(); }
  float A() const { return a_; }
  float B() const { return b_; }

 private:
  TexturedColor albedo_;
  float a_, b_;
};

// "oren-nayar" in the scene format (material_registry.h).
MaterialType orenNayarType();

}  // namespace verity
