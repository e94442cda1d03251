// A sphere (Embree's point-sphere primitive). Its transform must be a similarity so that it
// stays a sphere; uv follow its local axes (y up), as a lat-long map.
#pragma once

#include "core/transform.h"
#include "shapes/shape.h"
#include "shapes/shape_type.h"

namespace verity {

class Sphere : public Shape {
 public:
  // `toWorld` must be a similarity (checked by the loader).
  Sphere(const Transform& toWorld, float radius);

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  void completeHit(const Ray& ray, const RTCHit& hit, float t,
                   SurfaceInteraction& si) const override;
  Bounds3f bounds() const override;
  float area() const override { return 4 * kPi * radius_ * radius_; }
  ShapeSample sampleArea(const Point2f& u) const override;
  std::optional<ShapeSample> sampleSolidAngle(const Point3f& ref, const Point2f& u) const override;
  float pdfSolidAngle(const Point3f& ref, const Point3f& p, const Normal3f& n) const override;
  // Exactly the visible cone's, 2π(1 − cos θmax); 2π from inside.
  double solidAngleEstimate(const Point3f& ref) const override;
  size_t primitiveCount() const override { return 1; }

  const Point3f& center() const { return center_; }
  float radius() const { return radius_; }

 private:
  Point3f center_;
  float radius_;
  Vector3f pError_;
  Matrix3f rotation_;  // local axes in world space (columns)
};

// The scene format's "sphere".
ShapeType sphereType();

}  // namespace verity
