// Emitters as seen by the integrators: sampled from a reference point (next-event
// estimation), evaluated when a path hits them, and weighed by power for light selection.
#pragma once

#include <optional>

#include "core/math.h"

namespace verity {

struct LightSample {
  Color3 radiance = Color3::Zero();  // emitted towards the reference point
  Vector3f wi = Vector3f::UnitZ();   // unit direction from the reference point to the light
  Point3f p = Point3f::Zero();       // the point on the light (unused at infinity)
  Normal3f n = Normal3f::UnitZ();
  Vector3f pError = Vector3f::Zero();  // bound on p's rounding error
  float pdf = 0;                       // per solid angle at the reference point
  bool atInfinity = false;
};

// A ray leaving a light, the start of a light subpath (Veach 1997, §10.2): its origin, its
// direction of travel and the densities of both. Area lights emit from their front side
// only, cosine-distributed; the environment emits parallel rays from a disk of the scene's
// bounding radius, perpendicular to the direction, placed outside the scene.
struct LightEmission {
  Point3f p = Point3f::Zero();         // origin
  Normal3f n = Normal3f::UnitZ();      // emitter normal (the direction of travel at infinity)
  Vector3f pError = Vector3f::Zero();  // bound on p's rounding error (on a shape)
  Vector3f d = Vector3f::UnitZ();      // unit direction of travel
  Color3 radiance = Color3::Zero();    // Le carried along d
  float pdfPos = 0;                    // per area: on the shape, or on the disk (environment)
  float pdfDir = 0;                    // per solid angle
  bool atInfinity = false;
};

class Light {
 public:
  virtual ~Light() = default;
  virtual std::optional<LightSample> sampleLi(const Point3f& ref, const Point2f& u) const = 0;
  // Luminance of the total emitted power (for choosing among lights); needs the scene's
  // bounding radius. In double precision: a bright or large emitter's power can exceed the
  // single-precision range even where its radiance does not.
  virtual double power(double sceneRadius) const = 0;
  // An estimate of what the light sends to a point at `ref`: the luminance of its radiance
  // times the solid angle it subtends there (Shape::solidAngleEstimate), for choosing a light
  // for next-event estimation. 0 only where none of its light can arrive.
  virtual double contributionEstimate(const Point3f& ref) const = 0;
  virtual bool isInfinite() const { return false; }
  // Samples an emitted ray: `uPos` chooses the origin, `uDir` the direction. The scene's
  // bounding sphere (center, radius) places the environment's emitting disk.
  virtual std::optional<LightEmission> sampleLe(const Point2f& uPos, const Point2f& uDir,
                                                const Point3f& sceneCenter,
                                                float sceneRadius) const = 0;

  size_t index = 0;  // position in the scene's light list, set by the scene
};

}  // namespace verity
