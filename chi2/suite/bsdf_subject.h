// A verity::Material as a BsdfModel (verity/chi2/bsdf_model.h), tested by the same
// BsdfModelSubject that checks other renderers' BSDFs: chi-square on the sphere of world
// directions and the per-sample checks (weight = eval·|cos θo|/pdf, sample pdf = pdf(),
// no NaN/Inf/negative values, generalised reciprocity with the material's own index inside
// and 1 outside, the importance-mode BSDF as the adjoint).
//
// The shading normal may be rotated away from the geometric +z: the incident direction is
// given in world space and left unchanged, and is transformed into the local frame of the
// rotated normal, as the renderer does at a bump- or normal-mapped surface.
#pragma once

#include <verity/chi2/bsdf_model_subject.h>

#include <memory>

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

// The material evaluated in single precision at the default texture query, in radiance
// mode, with importance mode as the adjoint.
BsdfModel materialModel(std::shared_ptr<const Material> material);

class BsdfSubject : public BsdfModelSubject {
 public:
  explicit BsdfSubject(const BsdfSetup& setup);
  std::string describe() const override { return description_; }

 private:
  std::string description_;
};

// The incident direction at `degrees` from +z in the xz-plane, from below when `inside`.
Vector3f incidentDirection(double degrees, bool inside);

}  // namespace verity::chi2
