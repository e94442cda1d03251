// A perfect mirror: a Dirac delta lobe in the mirror direction, throughput `albedo`
// (DIRT's "metal" with roughness 0, whose albedo is the reflectance at every angle).
#pragma once

#include "materials/material.h"

namespace verity {

class Mirror : public Material {
 public:
  explicit Mirror(TexturedColor albedo) : albedo_(std::move(albedo)) {}

  Color3 eval(const TextureQuery&, const Vector3f&, const Vector3f&, TransportMode) const override {
    return Color3::Zero();
  }
  float pdf(const TextureQuery&, const Vector3f&, const Vector3f&) const override { return 0; }
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override;
  uint32_t lobes() const override { return kReflection | kSpecular; }
  bool isTextured() const override { return !albedo_.isConstant(); }

 private:
  TexturedColor albedo_;
};

}  // namespace verity
