#include "families.h"

#include <pbrt/util/spectrum.h>

#include <algorithm>
#include <cmath>
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

// Fresnel's reflectance of a dielectric of relative index eta (below / above) for cos θ on
// either side (Born and Wolf, §1.5.2), in double: the expectation is the exact value, which
// pbrt's FrDielectric computes in its own precision.
double fresnel(double cosI, double eta) {
  if (cosI < 0) eta = 1 / eta, cosI = -cosI;
  const double sin2T = (1 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1) return 1;
  const double cosT = std::sqrt(1 - sin2T);
  const double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return (rs * rs + rp * rp) / 2;
}

// A lobe's expected share, and its albedo where the lobe is drawn often enough to test it: a
// share of at least 10⁻⁴ is some 180 of the 1.8·10⁶ draws a delta-only check makes, while at
// η 1.0001 a reflection of 10⁻⁹ is never drawn and its albedo cannot be tested (its share is).
void expect(verity::chi2::BsdfCheckOptions& check, verity::chi2::DeltaLobe lobe, double share,
            double albedo) {
  verity::chi2::DeltaExpectation& e = check.delta.expect(lobe);
  e.share = share;
  if (share >= 1e-4) e.albedo = Eigen::ArrayXd::Constant(1, albedo);
}

// Smooth glass (pbrt's DielectricBxDF when its distribution is effectively smooth, α < 10⁻³):
// reflection with Fresnel's R and weight 1, refraction with 1 − R and, radiance being scaled by
// 1/η'² across the interface (η' the index across, seen from wi), weight 1/η'².
void expectSmoothDielectric(const verity::chi2::FamilyConfiguration& c,
                            verity::chi2::BsdfCheckOptions& check) {
  if (c.values[1] >= 1e-3) return;  // pbrt's EffectivelySmooth: max(αx, αy) < 10⁻³
  const double eta = c.values[0], cosI = c.wi().z(), r = fresnel(cosI, eta);
  const double across = cosI > 0 ? eta : 1 / eta;
  expect(check, verity::chi2::DeltaLobe::Reflection, r, r);
  expect(check, verity::chi2::DeltaLobe::Refraction, 1 - r, (1 - r) / (across * across));
}

// Thin glass: the light reflected inside the slab summed into R = F + T²F/(1 − F²), the rest
// straight through; each lobe weighs 1.
void expectThinDielectric(const verity::chi2::FamilyConfiguration& c,
                          verity::chi2::BsdfCheckOptions& check) {
  const double f = fresnel(std::fabs(c.wi().z()), c.values[0]), t = 1 - f;
  const double r = f < 1 ? f + t * t * f / (1 - f * f) : f;
  expect(check, verity::chi2::DeltaLobe::Reflection, r, r);
  expect(check, verity::chi2::DeltaLobe::PassThrough, 1 - r, 1 - r);
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
  out.push_back(
      {"dielectric",
       "DielectricBxDF(eta, TrowbridgeReitz(alpha, alpha))",
       {{"eta", 1.0001, 3, true}, alpha("alpha")},
       [](const V& v) {
         const auto eta = static_cast<pbrt::Float>(v[0]);
         return bxdfModel(pbrt::DielectricBxDF(eta, roughness(v[1], v[1])), 1, eta);
       },
       true,
       false,
       [](const auto& c, const auto&, auto& check) { expectSmoothDielectric(c, check); }});
  out.push_back({"thin-dielectric",
                 "ThinDielectricBxDF(eta)",
                 {{"eta", 1.0001, 3, true}},
                 // Thin glass refracts twice: what passes goes straight through, so the check
                 // holds its transmission to -wi (a model of index 1 on both sides).
                 [](const V& v) {
                   return bxdfModel(pbrt::ThinDielectricBxDF(static_cast<pbrt::Float>(v[0])));
                 },
                 true,
                 false,
                 [](const auto& c, const auto&, auto& check) { expectThinDielectric(c, check); }});
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
