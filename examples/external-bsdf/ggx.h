// A rough conductor with the GGX microfacet distribution (Walter et al. 2007, "Microfacet
// models for refraction through rough surfaces", EGSR): D from eq. 33, Smith's separable
// shadowing G1 from eq. 34, normals sampled by D(m)·cos θm (eqs. 35-36) and reflected, so
// that pdf(wo) = D(m)·cos θm / (4·|wo·m|) (eq. 14); Schlick's Fresnel with an RGB F0. The
// local frame has the normal along +z and both directions point away from the surface.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "vec3.h"

namespace example {

struct GgxSample {
  Vec3 wo;
  Rgb weight;  // f·cos θo / pdf
  double pdf = 0;
};

class Ggx {
 public:
  // `forgetJacobian`: the deliberate bug of the broken variant, pdf(wo) = D(m)·cos θm, the
  // density of the normal, without the reflection's Jacobian 1/(4|wo·m|).
  Ggx(double alpha, Rgb f0, bool forgetJacobian = false)
      : alpha_(alpha), f0_(f0), forgetJacobian_(forgetJacobian) {}

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    if (wi.z <= 0 || wo.z <= 0) return {};
    const Vec3 m = normalize(wi + wo);
    const double s = D(m) * G1(wi) * G1(wo) / (4 * wi.z * wo.z);
    const Rgb f = fresnel(dot(wi, m));
    return {s * f.r, s * f.g, s * f.b};
  }

  double pdf(const Vec3& wi, const Vec3& wo) const {
    if (wi.z <= 0 || wo.z <= 0) return 0;
    const Vec3 m = normalize(wi + wo);
    const double normalPdf = D(m) * m.z;
    return forgetJacobian_ ? normalPdf : normalPdf / (4 * dot(wo, m));
  }

  std::optional<GgxSample> sample(const Vec3& wi, double u0, double u1) const {
    if (wi.z <= 0) return std::nullopt;
    // tan²θm = α²·u0 / (1 − u0), φm = 2π·u1.
    const double tan2 = alpha_ * alpha_ * u0 / (1 - u0);
    const double cosM = 1 / std::sqrt(1 + tan2), sinM = std::sqrt(std::max(0.0, 1 - cosM * cosM));
    const double phi = 2 * kPi * u1;
    const Vec3 m{sinM * std::cos(phi), sinM * std::sin(phi), cosM};
    const Vec3 wo = 2 * dot(wi, m) * m + (-1.0) * wi;
    if (wo.z <= 0) return std::nullopt;  // reflected below the surface
    GgxSample s;
    s.wo = wo;
    s.pdf = pdf(wi, wo);
    const Rgb f = eval(wi, wo);
    const double c = wo.z / s.pdf;
    s.weight = {f.r * c, f.g * c, f.b * c};
    return s;
  }

 private:
  double D(const Vec3& m) const {
    if (m.z <= 0) return 0;
    const double a2 = alpha_ * alpha_, c2 = m.z * m.z, t = (a2 - 1) * c2 + 1;
    return a2 / (kPi * t * t);
  }
  double G1(const Vec3& v) const {
    const double c2 = v.z * v.z, tan2 = (1 - c2) / c2;
    return 2 / (1 + std::sqrt(1 + alpha_ * alpha_ * tan2));
  }
  Rgb fresnel(double cosine) const {
    const double k = std::pow(1 - cosine, 5);
    return {f0_.r + (1 - f0_.r) * k, f0_.g + (1 - f0_.g) * k, f0_.b + (1 - f0_.b) * k};
  }

  double alpha_;
  Rgb f0_;
  bool forgetJacobian_;
};

}  // namespace example
