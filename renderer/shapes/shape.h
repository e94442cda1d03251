// Geometry: registers itself with Embree, completes hits into surface interactions, and
// samples points on itself (for area lights).
#pragma once

#include <embree3/rtcore.h>

#include <optional>

#include "shapes/interaction.h"

namespace verity {

struct ShapeSample {
  Point3f p = Point3f::Zero();
  Normal3f n = Normal3f::UnitZ();      // geometric normal on the front side
  Vector3f pError = Vector3f::Zero();  // bound on p's rounding error, per component
  float pdf = 0;                       // per area, or per solid angle at the reference point
};

struct Bounds3f {
  Point3f lo = Point3f::Constant(kInfinity), hi = Point3f::Constant(-kInfinity);
  void expand(const Point3f& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void expand(const Bounds3f& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool empty() const { return (lo.array() > hi.array()).any(); }
};

class Shape {
 public:
  virtual ~Shape() = default;

  // Adds the shape's Embree geometry to `scene`; returns its geometry id.
  virtual unsigned attach(RTCDevice device, RTCScene scene) const = 0;
  // Fills the interaction from Embree's hit record (primitive, u, v, distance).
  virtual void completeHit(const Ray& ray, const RTCHit& hit, float t,
                           SurfaceInteraction& si) const = 0;
  virtual Bounds3f bounds() const = 0;
  virtual float area() const = 0;
  // A point uniform by area; pdf per area.
  virtual ShapeSample sampleArea(const Point2f& u) const = 0;
  // A point as seen from `ref`; pdf per solid angle at ref. The default converts an area
  // sample; shapes with a better strategy (spheres: the visible cone) override both.
  virtual std::optional<ShapeSample> sampleSolidAngle(const Point3f& ref, const Point2f& u) const;
  virtual float pdfSolidAngle(const Point3f& ref, const Point3f& p, const Normal3f& n) const;
  // An estimate of the solid angle the shape's front side subtends at `ref`, at most 2π, for
  // choosing among lights: 0 only where no point of the front side faces ref. The default
  // takes the whole area at the distance of the bounds' centre (2π inside the bounds).
  virtual double solidAngleEstimate(const Point3f& ref) const;
  // Number of primitives (for statistics).
  virtual size_t primitiveCount() const = 0;

  const Material* material = nullptr;
  const AreaLight* light = nullptr;
};

// A bound, per component, on the rounding error of a point computed on a primitive from
// values whose magnitudes sum to `magnitude` (vertices, or a centre and a radius). Our own
// interpolation is within γ7 of it (Pharr, Jakob and Humphreys 2016, PBRT 3rd ed., §3.9.4).
// Embree's ray-primitive tests are not conservative and round in proportion to the same
// magnitudes: with 3 million rays per case, shapes/tests/intersection_scale_test.cpp finds
// self-intersections at 2 unit roundoffs and none at 3, so γ7 covers them with a margin;
// shapes/tests/ray_offset_families_test.cpp checks it with 10^7 rays per family of placements
// (planes through the origin, random rotations and translations, scales 1e-4 to 1e5). A
// component that is exactly zero (a floor at y = 0) has a zero bound: the floor under
// Embree's arithmetic there is kMinOffset (core/ray.cpp).
inline constexpr float kPointErrorRoundoffs = 7;
inline Vector3f pointErrorBound(const Vector3f& magnitude) {
  constexpr float kUnitRoundoff = 0x1p-24f;
  constexpr float factor =
      kPointErrorRoundoffs * kUnitRoundoff / (1 - kPointErrorRoundoffs * kUnitRoundoff);
  return factor * magnitude;
}

// The solid angle a small planar emitter of `area` at `centre`, facing along `n`, subtends at
// ref: area · cos / distance², at most 2π; 0 from behind it (it emits from its front only).
double planarSolidAngleEstimate(double area, const Point3f& centre, const Normal3f& n,
                                const Point3f& ref);

// Converts an area density at p (normal n) to a solid-angle density at ref.
float areaToSolidAngle(float pdfArea, const Point3f& ref, const Point3f& p, const Normal3f& n);

}  // namespace verity
