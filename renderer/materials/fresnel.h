// Fresnel reflectance of smooth interfaces, unpolarised light. Directions follow the
// material convention: cosines are taken against the (micro)normal on the outside.
#pragma once

#include "core/math.h"

namespace verity {

// Reflectance of a dielectric interface whose interior has relative index `eta`
// (interior / exterior). A negative `cosThetaI` means the light arrives from the interior;
// beyond the critical angle the result is exactly 1 (total internal reflection).
float fresnelDielectric(float cosThetaI, float eta);

// Reflectance of a conductor with complex index eta + i·k (relative to the exterior),
// from the exact complex-valued Fresnel equations; `cosThetaI` is clamped to [0, 1].
Color3 fresnelConductor(float cosThetaI, const Color3& eta, const Color3& k);

// Schlick's approximation (Schlick 1994, "An Inexpensive BRDF Model for Physically-based
// Rendering"): F0 + (1 − F0)(1 − cos θ)^5.
Color3 fresnelSchlick(float cosThetaI, const Color3& f0);

// Refracts `wi` (pointing away from the surface, on the side `n` points to) through the
// interface with normal `n`; `eta` = index on the far side / index on wi's side. Returns
// false on total internal reflection.
bool refract(const Vector3f& wi, const Vector3f& n, float eta, Vector3f& wt);

// Mirror reflection of `wi` about `n`.
inline Vector3f reflect(const Vector3f& wi, const Vector3f& n) {
  return 2.0f * wi.dot(n) * n - wi;
}

}  // namespace verity
