// The families of pbrt-v4's BxDFs that check_pbrt_bsdfs checks: each BxDF over the ranges of
// its parameters that pbrt's scene loader accepts.
#pragma once

#include <verity/chi2/family_check.h>

#include <functional>
#include <string>
#include <vector>

namespace pbrt_bsdfs {

// The envelope of pbrt's named metals (metal-*-eta, metal-*-k) over the visible range: a
// conductor's η and k at any sampled wavelength lie inside it.
struct MetalRange {
  double etaMin = 0, etaMax = 0, kMin = 0, kMax = 0;
  double lambdaMin = 0, lambdaMax = 0;  // nm
};

// Needs pbrt initialised (InitPBRT: the named spectra).
MetalRange namedMetalRange();

struct Family {
  std::string name;         // "dielectric"
  std::string description;  // what is built from the values
  std::vector<verity::chi2::FamilyParameter> parameters;
  verity::chi2::BsdfFamily bsdf;
  bool fromBelow = false;  // a BxDF that transmits is lit from below too
  // f and Sample_f are random estimates (pbrt's layered BxDFs): checked in the mean-weight
  // mode (FamilyOptions::stochastic).
  bool stochastic = false;
  // What each configuration's check states beside the family's options: the delta lobes'
  // shares and albedos where Fresnel's equations give them (FamilyOptions::configure).
  std::function<void(const verity::chi2::FamilyConfiguration&, const verity::chi2::BsdfModel&,
                     verity::chi2::BsdfCheckOptions&)>
      configure;
};

// layeredMaxDepth: the random walks' bounces in the layered BxDFs (pbrt's coated materials'
// "maxdepth", 10 by default).
std::vector<Family> families(const MetalRange& metals, int layeredMaxDepth);

}  // namespace pbrt_bsdfs
