#include "camera/camera.h"

#include "sampling/warp.h"

namespace verity {

Camera::Camera(const Transform& toWorld, const Vector2i& resolution, float vfovDegrees,
               float focusDistance, float lensRadius)
    : toWorld_(toWorld),
      resolution_(resolution),
      focusDistance_(focusDistance),
      lensRadius_(lensRadius) {
  halfHeight_ = std::tan(degToRad(vfovDegrees) / 2);
  halfWidth_ =
      halfHeight_ * static_cast<float>(resolution.x()) / static_cast<float>(resolution.y());
}

Ray Camera::generateRay(const Point2f& film, const Point2f& lens) const {
  const float x = (2 * film.x() / resolution_.x() - 1) * halfWidth_;
  const float y = (1 - 2 * film.y() / resolution_.y()) * halfHeight_;
  Vector3f dir(x, y, -1);
  Point3f origin = Point3f::Zero();
  if (lensRadius_ > 0) {
    const Point2f l = lensRadius_ * warp::squareToUniformDiskConcentric(lens);
    const Point3f focus = dir * focusDistance_;
    origin = Point3f(l.x(), l.y(), 0);
    dir = focus - origin;
  }
  return Ray(toWorld_.point(origin), toWorld_.vector(dir).normalized());
}

}  // namespace verity
