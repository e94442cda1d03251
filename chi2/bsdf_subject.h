// A material's sample() tested against its pdf() on the sphere of world directions, with
// the per-sample checks: weight = eval·|cos θo|/pdf and sample pdf = pdf() to 1e-4
// relative, no NaN/Inf/negative values, and generalised reciprocity (Veach 1997, §5.3.2):
// for radiance transport eval(wi,wo)·ηo² = eval(wo,wi)·ηi², η being the index on each
// direction's side, and the importance-mode BSDF is the adjoint, eval*(wi,wo) = eval(wo,wi).
//
// The shading normal may be rotated away from the geometric +z: the incident direction is
// given in world space and left unchanged, and is transformed into the local frame of the
// rotated normal, as the renderer does at a bump- or normal-mapped surface.
#pragma once

#include <atomic>
#include <memory>

#include "chi2/core/subject.h"
#include "core/frame.h"
#include "materials/material.h"

namespace verity::chi2 {

struct BsdfSetup {
  std::string name;
  std::shared_ptr<const Material> material;
  Vector3f normal = Vector3f::UnitZ();  // shading normal in world space
  Vector3f wi = Vector3f::UnitZ();      // incident direction in world space
  bool checkReciprocity = true;
  int resolution = 32;  // cells in cos θ; twice as many in φ
};

class BsdfSubject : public Subject {
 public:
  explicit BsdfSubject(BsdfSetup setup);
  const Domain& domain() const override { return domain_; }
  double pdf(double phi, double z) const override;
  std::optional<Point2d> sample(pcg32& rng, Audit& audit) const override;
  void extraChecks(Audit& audit) const override;
  std::vector<double> breakpointsY(double phi) const override;
  // The mirror direction of wi about the shading normal and, for a dielectric, its
  // refracted direction (where a lobe narrows to a spike as α → 0 or η → 1).
  std::vector<Point2d> peaks() const override;
  std::string describe() const override;

  const Vector3f& wiLocal() const { return wiLocal_; }
  long long deltaSamples() const { return delta_.load(); }

 private:
  void checkPair(const Vector3f& wo, Audit& audit) const;

  BsdfSetup setup_;
  Frame frame_;
  Vector3f wiLocal_;
  Domain domain_;
  double ior_;  // the material's own index: the exterior is 1
  TextureQuery query_;
  mutable std::atomic<long long> delta_{0};
};

// The incident direction at `degrees` from +z in the xz-plane, from below when `inside`.
Vector3f incidentDirection(double degrees, bool inside);

}  // namespace verity::chi2
