// DIRT's area light material: emits constant radiance from its front side and scatters
// nothing.
#pragma once

#include "materials/material.h"
#include "materials/material_type.h"

namespace verity {

class DiffuseLight : public Material {
 public:
  explicit DiffuseLight(const Color3& emit) : emit_(emit) {}

  Color3 eval(const TextureQuery&, const Vector3f&, const Vector3f&, TransportMode) const override {
    return Color3::Zero();
  }
  float pdf(const TextureQuery&, const Vector3f&, const Vector3f&) const override { return 0; }
  std::optional<BsdfSample> sample(const TextureQuery&, const Vector3f&, float, const Point2f&,
                                   TransportMode) const override {
    return std::nullopt;
  }
  uint32_t lobes() const override { return kNoLobe; }
  Color3 emitted(const TextureQuery&, const Vector3f& w) const override {
    return w.z() > 0 ? emit_ : Color3::Zero();
  }
  bool isEmitter() const override { return !isBlack(emit_); }
  bool isTextured() const override { return false; }
  const Color3& radiance() const { return emit_; }

 private:
  Color3 emit_;
};

// "diffuse_light" in the scene format (material_registry.h).
MaterialType diffuseLightType();

}  // namespace verity
