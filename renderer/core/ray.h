// A ray segment o + t·d for t in [tmin, tmax].
#pragma once

#include "core/math.h"

namespace verity {

struct Ray {
  Point3f o = Point3f::Zero();
  Vector3f d = Vector3f::UnitZ();
  float tmin = 0.0f;
  float tmax = kInfinity;

  Ray() = default;
  Ray(const Point3f& origin, const Vector3f& dir, float tmaxValue = kInfinity)
      : o(origin), d(dir), tmax(tmaxValue) {}
  Point3f operator()(float t) const { return o + t * d; }
};

// Moves a ray origin off a surface by a few units in the last place along the geometric
// normal, so that the new ray does not hit the surface it starts on (Wächter and Binder
// 2019, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems,
// chapter 6). Their fixed-point threshold near the origin assumes a scene of unit size;
// `sceneScale` (the largest coordinate magnitude of the scene) makes it hold at any scale.
// `n` must point to the side the ray leaves towards.
Point3f offsetRayOrigin(const Point3f& p, const Normal3f& n, float sceneScale);

// A ray from p (on a surface with geometric normal ng) in direction d, offset to the side d
// points to.
Ray spawnRay(const Point3f& p, const Normal3f& ng, const Vector3f& d, float sceneScale);
// A shadow ray between two surface points, each offset to the side facing the other; it
// ends just before the target so that the target's own surface never occludes it.
Ray spawnRayTo(const Point3f& p, const Normal3f& ng, const Point3f& target,
               const Normal3f& ngTarget, float sceneScale);

}  // namespace verity
