// Deterministic checks of a microfacet distribution by quadrature:
//  - normalisation of the projected area, ∫ D(m) cos θm dm = 1 (Walter et al. 2007 eq. 4);
//  - the weak white furnace test (Heitz 2014, "Understanding the Masking-Shadowing
//    Function in Microfacet-Based BRDFs", JCGT 3(2), §3.3 / eq. 18): with F = 1 and no
//    shadowing, ∫ D(h) G1(wo, h) / (4 |cos θo|) dωi = 1. With dωi = 4 |wo·h| dh this is
//    ∫ G1(wo, m) max(0, wo·m) D(m) dm = cos θo (Heitz's eq. 2), which we integrate over m:
//    it fails whenever D and G1 disagree (G1 from another distribution).
#pragma once

#include <string>

#include "materials/microfacet.h"

namespace verity::chi2 {

inline constexpr double kNormalisationTolerance = 1e-4;
inline constexpr double kFurnaceTolerance = 1e-3;

struct MicrofacetCheck {
  std::string name;
  double value = 0, error = 0, tolerance = 0;
  bool passed = false;
  std::string describe() const;
};

// Integrand callbacks so that the broken variants of the tests can substitute a wrong D
// or G1; the defaults use the distribution's own.
MicrofacetCheck checkNormalisation(const MicrofacetDistribution& dist);
MicrofacetCheck checkWeakFurnace(const MicrofacetDistribution& dist, const Vector3f& wo);
MicrofacetCheck checkWeakFurnace(const MicrofacetDistribution& dMaster,
                                 const MicrofacetDistribution& g1Source, const Vector3f& wo);

// ∫ over the hemisphere of normals of f(m) dm, with breakpoints in θ at α/8·2^k so that
// a lobe of width α near the pole is resolved for every α ≥ 1e-4.
double integrateHemisphere(const std::function<double(const Vector3f&)>& f, double alpha,
                           double* error = nullptr);

}  // namespace verity::chi2
