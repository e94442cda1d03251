#include "families.h"

#include <pbrt/util/spectrum.h>

#include <algorithm>
#include <limits>

#include "pbrt_bxdf_model.h"

namespace pbrt_bsdfs {

namespace {

using pbrt::SampledSpectrum;
using pbrt::TrowbridgeReitzDistribution;

// A grey spectrum: the same value at every sampled wavelength, so that a family's parameter
// is what the BxDF sees at each of them.
SampledSpectrum grey(double value) {
  return SampledSpectrum(static_cast<pbrt::Float>(value));
}

TrowbridgeReitzDistribution roughness(double alphaX, double alphaY) {
  return TrowbridgeReitzDistribution(static_cast<pbrt::Float>(alphaX),
                                     static_cast<pbrt::Float>(alphaY));
}

// pbrt's microfacet roughness is α directly (its materials' "remaproughness" maps a user's
// roughness r to √r first). Below α = 10⁻³ TrowbridgeReitzDistribution is effectively smooth and
// the BxDF samples a delta lobe, so the range from 10⁻⁴ covers both regimes and the switch.
verity::chi2::FamilyParameter alpha(const char* name) {
  return {name, 1e-4, 1, true};
}

}  // namespace

MetalRange namedMetalRange() {
  MetalRange r{std::numeric_limits<double>::max(),
               0,
               std::numeric_limits<double>::max(),
               0,
               pbrt::Lambda_min,
               pbrt::Lambda_max};
  for (const char* metal : {"Ag", "Al", "Au", "Cu", "CuZn", "MgO", "TiO2"}) {
    const pbrt::Spectrum eta = pbrt::GetNamedSpectrum(std::string("metal-") + metal + "-eta");
    const pbrt::Spectrum k = pbrt::GetNamedSpectrum(std::string("metal-") + metal + "-k");
    for (double lambda = r.lambdaMin; lambda <= r.lambdaMax; lambda += 1) {
      r.etaMin = std::min<double>(r.etaMin, eta(lambda));
      r.etaMax = std::max<double>(r.etaMax, eta(lambda));
      r.kMin = std::min<double>(r.kMin, k(lambda));
      r.kMax = std::max<double>(r.kMax, k(lambda));
    }
  }
  return r;
}

std::vector<Family> families(const MetalRange& metals, int layeredMaxDepth) {
  using V = std::vector<double>;
  std::vector<Family> out;
  out.push_back({"diffuse", "DiffuseBxDF(R)", {{"R", 0, 1}}, [](const V& v) {
                   return bxdfModel(pbrt::DiffuseBxDF(grey(v[0])));
                 }});
  out.push_back(
      {"diffuse-transmission",
       "DiffuseTransmissionBxDF(R, T)",
       {{"R", 0, 1}, {"T", 0, 1}},
       [](const V& v) { return bxdfModel(pbrt::DiffuseTransmissionBxDF(grey(v[0]), grey(v[1]))); },
       true});
  out.push_back({"conductor",
                 "ConductorBxDF(TrowbridgeReitz(alpha, alpha), eta, k)",
                 {alpha("alpha"),
                  {"eta", metals.etaMin, metals.etaMax, true},
                  {"k", metals.kMin, metals.kMax}},
                 [](const V& v) {
                   return bxdfModel(
                       pbrt::ConductorBxDF(roughness(v[0], v[0]), grey(v[1]), grey(v[2])));
                 }});
  out.push_back({"conductor-anisotropic",
                 "ConductorBxDF(TrowbridgeReitz(alpha_x, alpha_y), 0.2, 3.5)",
                 {alpha("alpha_x"), alpha("alpha_y")},
                 [](const V& v) {
                   return bxdfModel(
                       pbrt::ConductorBxDF(roughness(v[0], v[1]), grey(0.2), grey(3.5)));
                 }});
  out.push_back({"dielectric",
                 "DielectricBxDF(eta, TrowbridgeReitz(alpha, alpha))",
                 {{"eta", 1.0001, 3, true}, alpha("alpha")},
                 [](const V& v) {
                   const auto eta = static_cast<pbrt::Float>(v[0]);
                   return bxdfModel(pbrt::DielectricBxDF(eta, roughness(v[1], v[1])), 1, eta);
                 },
                 true});
  out.push_back({"thin-dielectric",
                 "ThinDielectricBxDF(eta)",
                 {{"eta", 1.0001, 3, true}},
                 // Thin glass refracts twice: what passes goes straight through, so the check
                 // holds its transmission to -wi (a model of index 1 on both sides).
                 [](const V& v) {
                   return bxdfModel(pbrt::ThinDielectricBxDF(static_cast<pbrt::Float>(v[0])));
                 },
                 true});
  // pbrt's layered BxDFs at the defaults of its coated materials (thickness 0.01, no medium
  // between the layers, nsamples 1; maxdepth layeredMaxDepth, pbrt's default 10): f and Sample_f
  // are random walks, seeded from the directions (and Sample_f's uniforms) and pbrt's --seed.
  out.push_back({"coated-diffuse",
                 "CoatedDiffuseBxDF(DielectricBxDF(eta, TrowbridgeReitz(alpha, alpha)), "
                 "DiffuseBxDF(R), 0.01, 0, 0, maxdepth, 1)",
                 {{"eta", 1.0001, 3, true}, alpha("alpha"), {"R", 0, 1}},
                 [layeredMaxDepth](const V& v) {
                   const pbrt::DielectricBxDF top(static_cast<pbrt::Float>(v[0]),
                                                  roughness(v[1], v[1]));
                   return bxdfModel(pbrt::CoatedDiffuseBxDF(top, pbrt::DiffuseBxDF(grey(v[2])),
                                                            0.01f, grey(0), 0, layeredMaxDepth, 1));
                 },
                 false,
                 true});
  out.push_back({"coated-conductor",
                 "CoatedConductorBxDF(DielectricBxDF(eta, TrowbridgeReitz(alpha, alpha)), "
                 "ConductorBxDF(TrowbridgeReitz(conductor_alpha, conductor_alpha), 0.2, 3.5), "
                 "0.01, 0, 0, maxdepth, 1)",
                 {{"eta", 1.0001, 3, true}, alpha("alpha"), alpha("conductor_alpha")},
                 [layeredMaxDepth](const V& v) {
                   const pbrt::DielectricBxDF top(static_cast<pbrt::Float>(v[0]),
                                                  roughness(v[1], v[1]));
                   const pbrt::ConductorBxDF bottom(roughness(v[2], v[2]), grey(0.2), grey(3.5));
                   return bxdfModel(pbrt::CoatedConductorBxDF(top, bottom, 0.01f, grey(0), 0,
                                                              layeredMaxDepth, 1));
                 },
                 false,
                 true});
  return out;
}

}  // namespace pbrt_bsdfs
