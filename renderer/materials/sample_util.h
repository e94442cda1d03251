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

// A direction renormalised in double precision, for the lobes narrower than single precision
// resolves (a Phong exponent of 1e6 is 1e-3 rad wide, α = 1e-4 is 1e-4 rad): a float
// direction near (−1, 0, 0) keeps its direction in its small components, but its x is
// rounded to 6e-8, so that 1 − cos of its angle to a nearby direction, or the half vector
// with a grazing wi, read in single precision is off by more than the lobe's width. The
// double normalisation recovers x from the small components to 1e-16.
inline Eigen::Vector3d unitDouble(const Vector3f& v) {
  // One division, not Eigen's three: within an ulp of v/|v|. A zero vector stays zero, as
  // Eigen's normalized() leaves it.
  const Eigen::Vector3d d = v.cast<double>();
  const double n = d.norm();
  return n > 0 ? Eigen::Vector3d(d * (1 / n)) : d;
}

// Clamps a value computed from textures or formulas to a finite, non-negative colour.
inline Color3 sanitize(const Color3& c) {
  return isFinite(c) ? c.max(0.0f) : Color3(Color3::Zero());
}
inline float sanitize(float v) {
  return std::isfinite(v) && v > 0 ? v : 0.0f;
}

}  // namespace verity
