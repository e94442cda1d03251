#include "camera/camera.h"

#include "sampling/warp.h"

namespace verity {

Camera::Camera(const Transform& toWorld, const Vector2i& resolution, float vfovDegrees,
               float focusDistance, float lensRadius)
    : toWorld_(toWorld),
      toCameraLinear_(toWorld.inverseMatrix().topLeftCorner<3, 3>()),
      toCameraOffset_(toWorld.inverseMatrix().topRightCorner<3, 1>()),
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

std::optional<Point2f> Camera::filmFromCameraSpace(const Point3f& lens, const Vector3f& dir) const {
  const float cosTheta = -dir.z();
  if (!(cosTheta > 0)) return std::nullopt;
  // The ray crosses the plane in focus (z = −fdist; z = −1 for a pinhole, whose rays all pass
  // through the origin) at the point generateRay aimed at; scaled back to distance 1 it is
  // the film position on the image plane.
  const float planeDepth = lensRadius_ > 0 ? focusDistance_ : 1.0f;
  const Point3f onPlane = lens + dir * (planeDepth / cosTheta);
  const float x = onPlane.x() / planeDepth, y = onPlane.y() / planeDepth;
  const Point2f film((x / halfWidth_ + 1) * 0.5f * resolution_.x(),
                     (1 - y / halfHeight_) * 0.5f * resolution_.y());
  if (!(film.x() >= 0 && film.y() >= 0 && film.x() < resolution_.x() && film.y() < resolution_.y()))
    return std::nullopt;
  return film;
}

std::optional<Point2f> Camera::filmPosition(const Point3f& lensPoint, const Vector3f& d) const {
  return filmFromCameraSpace(toCameraPoint(lensPoint), toCameraDirection(d));
}

float Camera::importanceOf(const Vector3f& dir) const {
  const float cos2 = dir.z() * dir.z();
  return 1.0f / (imagePlaneArea() * lensArea() * cos2 * cos2);
}

float Camera::importance(const Point3f& lensPoint, const Vector3f& d, Point2f* film) const {
  const Vector3f dir = toCameraDirection(d);
  const auto position = filmFromCameraSpace(toCameraPoint(lensPoint), dir);
  if (!position) return 0;
  if (film) *film = *position;
  return importanceOf(dir);
}

void Camera::pdfImportance(const Point3f& lensPoint, const Vector3f& d, float* pdfPos,
                           float* pdfDir) const {
  const Vector3f dir = toCameraDirection(d);
  *pdfPos = 1.0f / lensArea();
  const float cosTheta = -dir.z();
  *pdfDir = 0;
  if (!(cosTheta > 0)) return;
  *pdfDir = 1.0f / (imagePlaneArea() * cosTheta * cosTheta * cosTheta);
}

Point3f Camera::sampleLens(const Point2f& u) const {
  if (!(lensRadius_ > 0)) return Point3f::Zero();
  const Point2f l = lensRadius_ * warp::squareToUniformDiskConcentric(u);
  return Point3f(l.x(), l.y(), 0);
}

std::optional<CameraImportanceSample> Camera::sampleImportance(const Point3f& ref,
                                                               const Point2f& u) const {
  const Point3f lens = sampleLens(u);
  CameraImportanceSample s;
  s.lensPoint = toWorld_.point(lens);
  const Vector3f toLens = s.lensPoint - ref;
  s.distance = toLens.norm();
  if (!(s.distance > 0)) return std::nullopt;
  s.wi = toLens / s.distance;
  const Vector3f dir = toCameraDirection(-s.wi);
  const auto film = filmFromCameraSpace(lens, dir);
  if (!film) return std::nullopt;
  s.film = *film;
  const float cosTheta = -dir.z();
  s.importance = importanceOf(dir);
  s.pdf = s.distance * s.distance / (cosTheta * lensArea());
  if (!std::isfinite(s.pdf) || !std::isfinite(s.importance)) return std::nullopt;
  return s;
}

std::optional<CameraImportanceSample> Camera::sampleImportanceFromInfinity(
    const Vector3f& towardsEnvironment, const Point2f& u) const {
  const Point3f lens = sampleLens(u);
  const Vector3f dir = toCameraDirection(towardsEnvironment);
  const auto film = filmFromCameraSpace(lens, dir);
  if (!film) return std::nullopt;
  CameraImportanceSample s;
  s.lensPoint = toWorld_.point(lens);
  s.wi = -towardsEnvironment.normalized();
  s.distance = kInfinity;
  s.film = *film;
  s.importance = importanceOf(dir);
  s.pdf = 1.0f / (-dir.z() * lensArea());
  if (!std::isfinite(s.pdf) || !std::isfinite(s.importance)) return std::nullopt;
  return s;
}

}  // namespace verity
