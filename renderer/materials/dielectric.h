// Smooth glass: a delta reflection and a delta refraction, chosen in proportion to the
// exact Fresnel reflectance. `ior` is the interior index over the exterior one; a
// direction with wi.z < 0 is inside.
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"

namespace verity {

// Samples the smooth interface of relative index `eta` (also used by RoughDielectric when
// it is index-matched). Reflection and refraction each have throughput 1 once divided by
// their selection probability, except that refracted radiance is scaled by 1/η² (η =
// index of the far side over that of wi's side), which importance is not (Veach 1997, §5.2).
std::optional<BsdfSample> sampleSmoothDielectric(const Vector3f& wi, float eta, float uLobe,
                                                 TransportMode mode);

class Dielectric : public Material {
 public:
  explicit Dielectric(float ior) : ior_(ior) {}

  Color3 eval(const TextureQuery&, const Vector3f&, const Vector3f&, TransportMode) const override {
    return Color3::Zero();
  }
  float pdf(const TextureQuery&, const Vector3f&, const Vector3f&) const override { return 0; }
  std::optional<BsdfSample> sample(const TextureQuery&, const Vector3f& wi, float uLobe,
                                   const Point2f&, TransportMode mode) const override {
    return sampleSmoothDielectric(wi, ior_, uLobe, mode);
  }
  uint32_t lobes() const override { return kReflection | kTransmission | kSpecular; }
  bool isTextured() const override { return false; }
  float interiorIndex() const override { return ior_; }

 private:
  float ior_;
};

// "dielectric" in the scene format (material_registry.h).
MaterialType dielectricType();

}  // namespace verity
