// A perspective camera looking down its local −z axis with +y up: a pinhole, or a thin
// lens of radius `aperture` focused at distance `fdist`. Image rows run downwards.
#pragma once

#include <optional>

#include "core/ray.h"
#include "core/transform.h"

namespace verity {

// A point on the lens chosen to connect a reference point to the camera (light tracing).
struct CameraImportanceSample {
  float importance = 0;             // We of the ray from the lens point towards the reference
  Vector3f wi = Vector3f::UnitZ();  // unit direction from the reference point to the lens
  float distance = 0;               // from the reference point to the lens point
  float pdf = 0;  // per solid angle at the reference point (the lens position density)
  Point3f lensPoint = Point3f::Zero();
  Point2f film = Point2f::Zero();  // where the connecting ray lands, in pixels
};

class Camera {
 public:
  Camera(const Transform& toWorld, const Vector2i& resolution, float vfovDegrees,
         float focusDistance, float lensRadius);

  // A ray through film position `film` (in pixels, x right, y down) and lens sample `lens`.
  Ray generateRay(const Point2f& film, const Point2f& lens) const;

  const Vector2i& resolution() const { return resolution_; }
  const Transform& toWorld() const { return toWorld_; }

  // Importance for light transport (Veach 1997, §10.2; pbrt-v3 §16.1.1), normalised over the
  // whole image: ∫_lens ∫ We(x, ω) cos θ dω dA(x) = 1. With A the area of the image plane at
  // distance 1, We = 1 / (A · lensArea · cos⁴θ) inside the image and 0 outside, θ measured
  // from the optical axis. A pixel's measurement is then resolution.x · resolution.y times the
  // integral restricted to that pixel. A pinhole's position is a Dirac delta: lensArea() is 1
  // for it and its position density is 1.
  float imagePlaneArea() const { return 4 * halfWidth_ * halfHeight_; }
  float lensArea() const { return lensRadius_ > 0 ? kPi * lensRadius_ * lensRadius_ : 1.0f; }
  // Film position (pixels) of the ray leaving the lens at world point `lensPoint` in world
  // direction `d`: what generateRay(film, ·) would have produced it from. nullopt when the
  // ray points away from the image or lands outside it.
  std::optional<Point2f> filmPosition(const Point3f& lensPoint, const Vector3f& d) const;
  // We of that ray (0 outside the image); its film position goes to `film` if given.
  float importance(const Point3f& lensPoint, const Vector3f& d, Point2f* film = nullptr) const;
  // Densities with which generateRay() (film and lens uniform) produces that ray: per area on
  // the lens (1 for a pinhole) and per solid angle, 1 / (A · cos³θ). For rays known to be in
  // the image (the image bounds are not checked, so that rounding at its edges cannot zero
  // the density of a ray generateRay made); 0 only for rays pointing backwards.
  void pdfImportance(const Point3f& lensPoint, const Vector3f& d, float* pdfPos,
                     float* pdfDir) const;
  // Chooses a lens point (uniform on the lens) seen from `ref`; nullopt when the connecting
  // ray misses the image. The pdf is per solid angle at ref: distance² / (cos θ · lensArea).
  std::optional<CameraImportanceSample> sampleImportance(const Point3f& ref,
                                                         const Point2f& u) const;
  // The same for light arriving from infinity, travelling along -towardsEnvironment (an
  // emitting background seen directly). The distance is infinite and the pdf is per unit area
  // perpendicular to the direction: 1 / (cos θ · lensArea), the limit of the solid-angle
  // density above times distance⁻² (the convention of path_vertex.h at infinity).
  std::optional<CameraImportanceSample> sampleImportanceFromInfinity(
      const Vector3f& towardsEnvironment, const Point2f& u) const;

 private:
  Transform toWorld_;
  // World to camera space, kept apart from the 4×4 inverse for the per-connection queries.
  Eigen::Matrix3f toCameraLinear_;
  Vector3f toCameraOffset_;
  Vector2i resolution_;
  float halfHeight_, halfWidth_;  // of the image plane at distance 1
  float focusDistance_, lensRadius_;

  // World points, and world directions as unit vectors, in camera space.
  Point3f toCameraPoint(const Point3f& p) const { return toCameraLinear_ * p + toCameraOffset_; }
  Vector3f toCameraDirection(const Vector3f& d) const { return (toCameraLinear_ * d).normalized(); }
  // A lens point in camera space, uniform on the lens (the origin for a pinhole).
  Point3f sampleLens(const Point2f& u) const;
  // We of the camera-space unit direction `dir` (camera-space cos θ = −dir.z()).
  float importanceOf(const Vector3f& dir) const;
  // The film position that camera-space unit direction `dir` reaches from camera-space lens
  // point `lens` (film plane at distance 1).
  std::optional<Point2f> filmFromCameraSpace(const Point3f& lens, const Vector3f& dir) const;
};

}  // namespace verity
