#include "chi2/suite/microfacet_checks.h"

#include <fmt/format.h>
#include <verity/chi2/quadrature.h>

#include <numbers>

namespace verity::chi2 {

double integrateHemisphere(const std::function<double(const Vector3f&)>& f, double alpha,
                           double* error) {
  const double halfPi = std::numbers::pi / 2;
  QuadratureOptions q;  // the defaults: 1e-6 inner, 1e-5 outer, per θ interval
  double total = 0, err = 0;
  double t0 = 0;
  for (double t1 = alpha / 8; t0 < halfPi; t1 *= 2) {
    t1 = std::min(t1, halfPi);
    double e = 0;
    total += integrate2D(
        [&](double theta, double phi) {
          const double s = std::sin(theta);
          const Vector3f m(float(s * std::cos(phi)), float(s * std::sin(phi)),
                           float(std::cos(theta)));
          return f(m) * s;
        },
        t0, t1, 0, 2 * std::numbers::pi, q, &e);
    err += e;
    t0 = t1;
  }
  if (error) *error = err;
  return total;
}

MicrofacetCheck checkNormalisation(const MicrofacetDistribution& dist) {
  MicrofacetCheck c;
  c.name = "normalisation of D(m) cos(theta_m)";
  c.tolerance = kNormalisationTolerance;
  c.value = integrateHemisphere([&](const Vector3f& m) { return double(dist.D(m)) * m.z(); },
                                dist.alpha(), &c.error);
  c.passed = std::fabs(c.value - 1) <= c.tolerance;
  return c;
}

MicrofacetCheck checkWeakFurnace(const MicrofacetDistribution& d, const MicrofacetDistribution& g,
                                 const Vector3f& wo) {
  MicrofacetCheck c;
  c.name = fmt::format("weak white furnace at theta_o = {:.4g} deg",
                       std::acos(std::clamp(double(wo.z()), -1.0, 1.0)) * 180 / std::numbers::pi);
  c.tolerance = kFurnaceTolerance;
  const double integral = integrateHemisphere(
      [&](const Vector3f& m) {
        return double(g.G1(wo, m)) * std::max(0.0, double(wo.dot(m))) * double(d.D(m));
      },
      d.alpha(), &c.error);
  c.value = integral / wo.z();
  c.error /= wo.z();
  c.passed = std::fabs(c.value - 1) <= c.tolerance;
  return c;
}

MicrofacetCheck checkWeakFurnace(const MicrofacetDistribution& dist, const Vector3f& wo) {
  return checkWeakFurnace(dist, dist, wo);
}

std::string MicrofacetCheck::describe() const {
  return fmt::format("[{}] {}: {:.7f} (expected 1 +- {:.0e}; quadrature error estimate {:.1e})",
                     passed ? "pass" : "FAIL", name, value, tolerance, error);
}

}  // namespace verity::chi2
