// Smooth glass in its own types, as pbrt-v4 writes it: Fresnel-chosen reflection or
// refraction, the refraction's radiance scaled by 1/η², and the expectations a check states
// for it (each lobe's share and albedo from Fresnel's equations).
#pragma once

#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/delta_check.h>

#include <cmath>
#include <optional>

#include "phong_toy.h"

namespace verity::chi2::glass_toy {

using phong_toy::Vec3;

struct Sample {
  Vec3 wo;
  double weight = 0;
  double pdf = 0;
  bool delta = true;
};

// Unpolarised Fresnel reflectance of a dielectric of relative index eta (below / above) for
// cos θi on either side.
inline double fresnel(double cosI, double eta) {
  if (cosI < 0) eta = 1 / eta, cosI = -cosI;
  const double sin2T = (1 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1) return 1;
  const double cosT = std::sqrt(1 - sin2T);
  const double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return (rs * rs + rp * rp) / 2;
}

inline Vec3 mirror(const Vec3& w) {
  return {-w.x, -w.y, w.z};
}

// A smooth dielectric of relative index eta, written as pbrt-v4 writes it.
struct Glass {
  double eta;
  bool forgetsRadianceScaling = false;  // a defect: the refraction's weight without 1/η²

  std::optional<Sample> sample(const Vec3& wi, double u) const {
    const double r = fresnel(wi.z, eta);
    if (u < r) return Sample{mirror(wi), 1, r};
    const double e = wi.z > 0 ? eta : 1 / eta, cosI = std::fabs(wi.z);
    const double cosT = std::sqrt(1 - (1 - cosI * cosI) / (e * e));
    const Vec3 t{-wi.x / e, -wi.y / e, wi.z > 0 ? -cosT : cosT};
    return Sample{t, forgetsRadianceScaling ? 1 : 1 / (e * e), 1 - r};
  }
};

// A purely delta, grey BSDF: eval and pdf are zero everywhere.
template <class SampleFn>
BsdfModel deltaModel(SampleFn sample) {
  return bsdfModel<Vec3>(
      sample, [](const Vec3&, const Vec3&) { return 0.0; },
      [](const Vec3&, const Vec3&) { return 0.0; });
}

inline BsdfModel glassModel(Glass g) {
  BsdfModel m =
      deltaModel([g](const Vec3& wi, const BsdfUniforms& u) { return g.sample(wi, u.lobe); });
  m.interiorIndex = g.eta;
  return m;
}

// The expectations of smooth glass of index eta at wi: Fresnel's share for each lobe, and
// the refraction's albedo scaled by 1/η'² (η' the index across, seen from wi).
inline void expectGlass(BsdfCheckOptions& o, const Vec3& wi, double eta) {
  const double r = fresnel(wi.z, eta), e = wi.z > 0 ? eta : 1 / eta;
  o.delta.eta = eta;
  o.delta.expect(DeltaLobe::Reflection) = {r, Eigen::ArrayXd::Constant(1, r)};
  o.delta.expect(DeltaLobe::Refraction) = {1 - r, Eigen::ArrayXd::Constant(1, (1 - r) / (e * e))};
}

}  // namespace verity::chi2::glass_toy
