// Shared checks that keep non-finite or negative values from leaving a material.
#pragma once

#include <optional>

#include "materials/material.h"

namespace verity {

// A non-delta sample from its value f (no cosine), its density and its lobe: nullopt when
// the density is not a positive finite number or the weight f·|cos θo|/pdf is not finite,
// so that the integrator never sees a garbage weight.
inline std::optional<BsdfSample> makeSample(const Vector3f& wo, const Color3& f, float pdf,
                                            uint32_t lobe, float eta = 1.0f) {
  if (!(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
  BsdfSample s;
  s.wo = wo;
  s.pdf = pdf;
  s.weight = f * (std::abs(wo.z()) / pdf);
  if (!isFinite(s.weight) || (s.weight < 0).any()) return std::nullopt;
  s.lobe = lobe;
  s.eta = eta;
  return s;
}

// Clamps a value computed from textures or formulas to a finite, non-negative colour.
inline Color3 sanitize(const Color3& c) {
  return isFinite(c) ? c.max(0.0f) : Color3(Color3::Zero());
}
inline float sanitize(float v) {
  return std::isfinite(v) && v > 0 ? v : 0.0f;
}

}  // namespace verity
