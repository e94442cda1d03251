// Orthonormal shading frame; directions in local coordinates have the normal along +z.
#pragma once

#include "core/math.h"

namespace verity {

// Builds tangents from a unit normal without branches on its direction
// (Duff et al. 2017, "Building an Orthonormal Basis, Revisited", JCGT 6(1)).
inline void coordinateSystem(const Vector3f& n, Vector3f& s, Vector3f& t) {
  const float sign = std::copysign(1.0f, n.z());
  const float a = -1.0f / (sign + n.z());
  const float b = n.x() * n.y() * a;
  s = Vector3f(1.0f + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  t = Vector3f(b, sign + n.y() * n.y() * a, -n.y());
}

struct Frame {
  Vector3f s = Vector3f::UnitX(), t = Vector3f::UnitY(), n = Vector3f::UnitZ();

  Frame() = default;
  explicit Frame(const Vector3f& normal) : n(normal) { coordinateSystem(n, s, t); }

  Vector3f toLocal(const Vector3f& v) const { return {v.dot(s), v.dot(t), v.dot(n)}; }
  Vector3f toWorld(const Vector3f& v) const { return s * v.x() + t * v.y() + n * v.z(); }

  static float sin2Theta(const Vector3f& v) { return std::max(0.0f, 1.0f - v.z() * v.z()); }
  static float sinTheta(const Vector3f& v) { return std::sqrt(sin2Theta(v)); }
};

}  // namespace verity
