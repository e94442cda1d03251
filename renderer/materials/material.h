// The interface every integrator uses to scatter light at a surface. Directions are unit
// vectors in the local shading frame (normal along +z) and both point away from the
// surface: `wi` towards where the path came from (the camera side for radiance), `wo`
// towards where it goes next.
#pragma once

#include <cstdint>
#include <optional>

#include "core/math.h"
#include "textures/texture.h"

namespace verity {

// Which quantity a path carries: radiance (paths from the camera) or importance (paths
// from lights). Refraction scales radiance by 1/η² but not importance (Veach 1997, §5.2).
enum class TransportMode { Radiance, Importance };

// Lobe flags, combinable.
enum Lobe : uint32_t {
  kNoLobe = 0,
  kReflection = 1u << 0,
  kTransmission = 1u << 1,
  kDiffuse = 1u << 2,
  kGlossy = 1u << 3,
  kSpecular = 1u << 4,  // a Dirac delta: eval and pdf are zero, only sample() reaches it
};

struct BsdfSample {
  Vector3f wo = Vector3f::UnitZ();
  Color3 weight = Color3::Zero();  // f·|cos θo| / pdf; for a delta lobe the lobe's throughput
  float pdf = 0.0f;                // solid-angle density; for a delta lobe, the lobe choice's
  uint32_t lobe = kNoLobe;
  // Relative index of refraction across a sampled transmission (1 otherwise).
  float eta = 1.0f;

  bool isDelta() const { return (lobe & kSpecular) != 0; }
};

class Material {
 public:
  virtual ~Material() = default;

  // f(wi, wo) without the cosine; zero for delta lobes.
  virtual Color3 eval(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo,
                      TransportMode mode) const = 0;
  // Solid-angle density of sample() producing wo; zero for delta lobes.
  virtual float pdf(const TextureQuery& q, const Vector3f& wi, const Vector3f& wo) const = 0;
  // `uLobe` chooses among lobes, `u` samples the chosen one. No sample (nullopt) when the
  // material cannot scatter from wi; never a sample with a non-finite or negative weight.
  virtual std::optional<BsdfSample> sample(const TextureQuery& q, const Vector3f& wi, float uLobe,
                                           const Point2f& u, TransportMode mode) const = 0;

  // The union of the lobes this material may sample; kNoLobe for a pure absorber (lights).
  virtual uint32_t lobes() const = 0;
  bool hasDeltaLobe() const { return (lobes() & kSpecular) != 0; }
  bool hasNonDeltaLobe() const { return (lobes() & (kDiffuse | kGlossy)) != 0; }

  // Radiance emitted towards local direction w (front side only for DIRT lights).
  virtual Color3 emitted(const TextureQuery& q, const Vector3f& w) const { return Color3::Zero(); }
  virtual bool isEmitter() const { return false; }
  // The index of refraction inside over outside of a material that transmits; 1 for one
  // that does not. Radiance crossing the interface scales by its square.
  virtual float interiorIndex() const { return 1; }
  // Whether any parameter varies over the surface (for the scene summary).
  virtual bool isTextured() const = 0;
};

}  // namespace verity
