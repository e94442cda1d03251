#include "core/ray.h"

#include <bit>
#include <cstdint>

namespace verity {

namespace {
// The next float after v away from zero in the direction of `sign` (std::nextafter without
// the library call: it is on the path of every spawned ray).
float stepFloat(float v, float sign) {
  if (std::isinf(v)) return v;
  if (v == 0) return std::copysign(std::numeric_limits<float>::denorm_min(), sign);
  const uint32_t bits = std::bit_cast<uint32_t>(v);
  const bool awayFromZero = (v >= 0) == (sign > 0);
  return std::bit_cast<float>(awayFromZero ? bits + 1 : bits - 1);
}
}  // namespace

// The least distance an origin moves off its surface. Embree's robust (Plücker) test computes
// a hit's distance as t = T·rcp(den), T = dot(v0 − o, Ng), and accepts tnear ≤ t: from an
// origin one denormal off an exact plane (y = 0, where p has no error in y) the product
// underflows to ±0 and the surface is found at its own origin, which made next-event
// estimation 21% dark in a Cornell box whose floor is at y = 0. At 2^-96 both T (for
// triangles down to areas of 2^-30) and t stay normal floats; no scene can resolve it.
constexpr float kMinOffset = 0x1p-96f;

Point3f offsetRayOrigin(const Point3f& p, const Vector3f& pError, const Normal3f& n,
                        const Vector3f& w) {
  // The distance to the plane through p that bounds the error box along n.
  const float distance = n.cwiseAbs().dot(pError) + kMinOffset;
  const Normal3f side = w.dot(n) < 0 ? Normal3f(-n) : n;
  Point3f origin = p + distance * side;
  // The sum is rounded too, and an exact point (no error) still must leave its plane: step
  // one float further in every component the normal moves.
  for (int i = 0; i < 3; ++i)
    if (side[i] != 0) origin[i] = stepFloat(origin[i], side[i]);
  return origin;
}

Ray spawnRay(const Point3f& p, const Vector3f& pError, const Normal3f& ng, const Vector3f& d) {
  return Ray(offsetRayOrigin(p, pError, ng, d), d);
}

Ray spawnRayTo(const Point3f& p, const Vector3f& pError, const Normal3f& ng, const Point3f& target,
               const Vector3f& targetError, const Normal3f& targetNg) {
  const Point3f from = offsetRayOrigin(p, pError, ng, target - p);
  const Point3f to = offsetRayOrigin(target, targetError, targetNg, from - target);
  return Ray(from, to - from, 1.0f - 1e-4f);
}

}  // namespace verity
