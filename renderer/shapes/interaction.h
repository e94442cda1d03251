// What a ray hit: the point, its frames and what is there.
#pragma once

#include "core/frame.h"
#include "core/ray.h"
#include "textures/texture.h"

namespace verity {

class Material;
class Shape;
class AreaLight;

struct SurfaceInteraction {
  Point3f p = Point3f::Zero();
  Normal3f ng = Normal3f::UnitZ();  // geometric normal, oriented as the shape's front side
  Frame shading;                    // shading frame; its normal is on ng's side
  Point2f uv = Point2f::Zero();
  float t = kInfinity;
  const Shape* shape = nullptr;
  const Material* material = nullptr;
  const AreaLight* light = nullptr;    // set when the surface emits
  Vector3f pError = Vector3f::Zero();  // bound on p's rounding error, per component

  TextureQuery textureQuery() const { return {uv, p}; }
  Vector3f toLocal(const Vector3f& v) const { return shading.toLocal(v); }
  Vector3f toWorld(const Vector3f& v) const { return shading.toWorld(v); }
  Ray spawnRay(const Vector3f& d) const { return verity::spawnRay(p, pError, ng, d); }
  Ray spawnRayTo(const Point3f& target, const Vector3f& targetError,
                 const Normal3f& targetNormal) const {
    return verity::spawnRayTo(p, pError, ng, target, targetError, targetNormal);
  }
  Ray spawnRayTo(const SurfaceInteraction& target) const {
    return spawnRayTo(target.p, target.pError, target.ng);
  }
};

}  // namespace verity
