// A linear blend of two materials: f = (1 − t)·f_a + t·f_b with t = `amount` (the weight
// of b). Sampling picks b with probability t and a otherwise, so the density of a
// non-delta direction is the mixture (1 − t)·p_a + t·p_b. A delta sample keeps the chosen
// material's weight (its contribution t·f_b and its probability t·p_b share the factor t).
// Neither material may emit: emitters are surfaces that carry a light (scene.cpp), and a
// blended emission would need a light of textured radiance; the scene loader refuses it.
#pragma once

#include <memory>

#include "materials/material.h"
#include "materials/material_type.h"

namespace verity {

class Blend : public Material {
 public:
  Blend(std::shared_ptr<const Material> a, std::shared_ptr<const Material> b, TexturedColor amount)
      : a_(std::move(a)), b_(std::move(b)), amount_(std::move(amount)) {}

  Color3 eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
              TransportMode mode) const override;
  float pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const override;
  std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                   const Point2f& u, TransportMode mode) const override;
  uint32_t lobes() const override { return a_->lobes() | b_->lobes(); }
  bool isTextured() const override {
    return !amount_.isConstant() || a_->isTextured() || b_->isTextured();
  }

 private:
  float amount(const TextureQuery& q) const;
  std::shared_ptr<const Material> a_, b_;
  TexturedColor amount_;
};

// "blend" in the scene format (material_registry.h).
MaterialType blendType();

}  // namespace verity
