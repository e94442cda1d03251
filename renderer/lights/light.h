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
  float pdf = 0;  // per solid angle at the reference point
  bool atInfinity = false;
};

class Light {
 public:
  virtual ~Light() = default;
  virtual std::optional<LightSample> sampleLi(const Point3f& ref, const Point2f& u) const = 0;
  // Total emitted power (for choosing among lights); needs the scene's bounding radius.
  virtual Color3 power(float sceneRadius) const = 0;
  virtual bool isInfinite() const { return false; }

  size_t index = 0;  // position in the scene's light list, set by the scene
};

}  // namespace verity
