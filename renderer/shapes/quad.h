// A parallelogram: the transformed square [-w/2, w/2] × [-h/2, h/2] of the local xy-plane,
// front side +z. Embree's quad primitive.
#pragma once

#include <array>

#include "core/transform.h"
#include "shapes/shape.h"
#include "shapes/shape_type.h"

namespace verity {

class Quad : public Shape {
 public:
  Quad(const Transform& toWorld, const Vector2f& size);

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  void completeHit(const Ray& ray, const RTCHit& hit, float t,
                   SurfaceInteraction& si) const override;
  Bounds3f bounds() const override;
  float area() const override { return area_; }
  ShapeSample sampleArea(const Point2f& u) const override;
  double solidAngleEstimate(const Point3f& ref) const override;
  size_t primitiveCount() const override { return 1; }
  // The corners in order around the boundary.
  std::array<Point3f, 4> corners() const {
    return {corner_, corner_ + edgeU_, corner_ + edgeU_ + edgeV_, corner_ + edgeV_};
  }

 private:
  Point3f corner_;  // local (-w/2, -h/2)
  Vector3f edgeU_, edgeV_;
  Normal3f normal_;
  Vector3f pError_;
  float area_;
};

// The scene format's "quad".
ShapeType quadType();

}  // namespace verity
