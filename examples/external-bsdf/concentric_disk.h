// Uniform points on the unit disk by the concentric map (Shirley & Chiu 1997, "A low
// distortion map between disk and square", JGT 2(3)), and the broken variant the example's
// test must see rejected: polar coordinates with the radius left linear in u, which crowds
// the centre (the right radius is √u).
#pragma once

#include <cmath>

#include "vec3.h"

namespace example {

inline Vec2 concentricDisk(const Vec2& u) {
  const double a = 2 * u.x - 1, b = 2 * u.y - 1;
  if (a == 0 && b == 0) return {};
  double r, phi;
  if (std::fabs(a) > std::fabs(b)) {
    r = a;
    phi = kPi / 4 * (b / a);
  } else {
    r = b;
    phi = kPi / 2 - kPi / 4 * (a / b);
  }
  return {r * std::cos(phi), r * std::sin(phi)};
}

inline Vec2 linearRadiusDisk(const Vec2& u) {
  const double phi = 2 * kPi * u.y;
  return {u.x * std::cos(phi), u.x * std::sin(phi)};
}

// Both claim the uniform density 1/π.
inline double diskPdf(const Vec2& p) {
  return p.x * p.x + p.y * p.y <= 1 ? 1 / kPi : 0;
}

}  // namespace example
