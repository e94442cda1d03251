// Hemisphere sampling for the toy Lambertian lobes of the adapter tests, written from the
// formulas in the toys' own vector type (phong_toy::Vec3).
#pragma once

#include <cmath>
#include <numbers>

#include "phong_toy.h"

namespace lambert_toy {

using phong_toy::Vec3;

// Malley's method on the polar map: r = √u0, pdf = cos θ / π.
inline Vec3 cosineHemisphere(double u0, double u1) {
  const double r = std::sqrt(u0), phi = 2 * std::numbers::pi * u1;
  return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u0))};
}
inline double cosinePdf(const Vec3& w) {
  return w.z > 0 ? w.z / std::numbers::pi : 0;
}

// z uniform in [0, 1): pdf = 1 / (2π) (Archimedes' hat-box theorem).
inline Vec3 uniformHemisphere(double u0, double u1) {
  const double z = u0, r = std::sqrt(std::max(0.0, 1 - z * z));
  const double phi = 2 * std::numbers::pi * u1;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
inline double uniformPdf(const Vec3& w) {
  return w.z > 0 ? 1 / (2 * std::numbers::pi) : 0;
}

}  // namespace lambert_toy
