// The warps of sampling/warp.h and the microfacet normal samplers of
// materials/microfacet.h as test subjects.
#pragma once

#include <verity/chi2/subject.h>

#include <memory>
#include <string>

#include "materials/microfacet.h"

namespace verity::chi2 {

enum class WarpKind {
  DiskPolar,
  DiskConcentric,
  UniformSphere,
  UniformHemisphere,
  CosineHemisphere,
  SphericalCap,
  Triangle,
  SquareIdentity,  // the unit square itself: a control for the square domain
};

// `parameter` is cos θmax for the spherical cap and unused otherwise.
std::unique_ptr<Subject> makeWarpSubject(WarpKind kind, float parameter, int resolution);

// Microfacet normals sampled for the direction wi (local, wi.z > 0) with the
// distribution's own sampling mode; the density is pdfNormal(wi, m).
std::unique_ptr<Subject> makeMicrofacetNormalSubject(const MicrofacetDistribution& dist,
                                                     const Vector3f& wi, int resolution);

std::string warpName(WarpKind kind);

}  // namespace verity::chi2
