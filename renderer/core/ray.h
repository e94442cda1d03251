// A ray segment o + t·d for t in [tmin, tmax], and rays that leave surfaces.
#pragma once

#include "core/math.h"

namespace verity {

// The largest coordinate magnitude a scene may have, camera and lens included: squared
// distances between its points stay finite in single precision, and the ray origins Embree
// accepts (below about 1.8e18) stay in range after the origin offsets.
inline constexpr float kMaxSceneCoordinate = 1e15f;

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

// Moves a ray origin off the surface it lies on, along the geometric normal `n` to the side
// `w` points to, past the rounding error of the point (`pError`, a bound per component) and
// then one float further in each moved component, so that the ray cannot hit the surface at
// its origin (Pharr, Jakob and Humphreys 2016, Physically Based Rendering, 3rd ed., §3.9.5).
// The offset depends only on the point's own error: a unit sphere keeps small offsets beside
// a floor a million units wide, and an axis-aligned plane at 0 is left by 2^-96 (kMinOffset in
// ray.cpp), the least distance at which Embree's hit distance does not underflow to zero.
Point3f offsetRayOrigin(const Point3f& p, const Vector3f& pError, const Normal3f& n,
                        const Vector3f& w);

// A ray from p (error bound pError, geometric normal ng) in direction d.
Ray spawnRay(const Point3f& p, const Vector3f& pError, const Normal3f& ng, const Vector3f& d);
// A shadow ray between two surface points, each offset to the side facing the other; it
// ends just before the target so that the target's own surface never occludes it.
Ray spawnRayTo(const Point3f& p, const Vector3f& pError, const Normal3f& ng, const Point3f& target,
               const Vector3f& targetError, const Normal3f& targetNg);

}  // namespace verity
