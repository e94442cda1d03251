// A perspective camera looking down its local −z axis with +y up: a pinhole, or a thin
// lens of radius `aperture` focused at distance `fdist`. Image rows run downwards.
#pragma once

#include "core/ray.h"
#include "core/transform.h"

namespace verity {

class Camera {
 public:
  Camera(const Transform& toWorld, const Vector2i& resolution, float vfovDegrees,
         float focusDistance, float lensRadius);

  // A ray through film position `film` (in pixels, x right, y down) and lens sample `lens`.
  Ray generateRay(const Point2f& film, const Point2f& lens) const;

  const Vector2i& resolution() const { return resolution_; }
  bool isPinhole() const { return lensRadius_ == 0; }
  const Transform& toWorld() const { return toWorld_; }
  Point3f position() const { return toWorld_.point(Point3f::Zero()); }

 private:
  Transform toWorld_;
  Vector2i resolution_;
  float halfHeight_, halfWidth_;  // of the image plane at distance 1
  float focusDistance_, lensRadius_;
};

}  // namespace verity
