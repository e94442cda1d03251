#include "materials/fresnel.h"

#include <complex>

namespace verity {

float fresnelDielectric(float cosThetaI, float eta) {
  cosThetaI = std::clamp(cosThetaI, -1.0f, 1.0f);
  if (cosThetaI < 0) {  // arriving from the interior: swap the media
    eta = 1.0f / eta;
    cosThetaI = -cosThetaI;
  }
  // At exactly grazing incidence both amplitude ratios are -1 (even for eta = 1, where the
  // formulas below would read 0/0).
  if (cosThetaI == 0) return 1.0f;
  const float sin2ThetaT = (1.0f - cosThetaI * cosThetaI) / (eta * eta);
  if (sin2ThetaT >= 1.0f) return 1.0f;
  const float cosThetaT = safeSqrt(1.0f - sin2ThetaT);
  // Amplitude ratios for s- and p-polarised light (Born and Wolf, "Principles of Optics",
  // §1.5.2), written with the relative index; both denominators are > 0 here.
  const float rs = (cosThetaI - eta * cosThetaT) / (cosThetaI + eta * cosThetaT);
  const float rp = (eta * cosThetaI - cosThetaT) / (eta * cosThetaI + cosThetaT);
  return std::clamp(0.5f * (rs * rs + rp * rp), 0.0f, 1.0f);
}

namespace {
// One wavelength of the complex Fresnel equations: Snell's law with a complex index gives
// a complex cos θt (principal square root, which is defined everywhere), then the same
// amplitude ratios as for a dielectric.
float conductorChannel(float cosThetaI, float eta, float k) {
  using C = std::complex<float>;
  const C n(eta, k), n2 = n * n;
  const float sin2ThetaI = 1.0f - cosThetaI * cosThetaI;
  // sin²θ / n² through the conjugate: std::complex division takes a slow library call.
  const C cosThetaT = std::sqrt(C(1.0f) - sin2ThetaI * std::conj(n2) / std::norm(n2));
  const float denS = std::norm(C(cosThetaI) + n * cosThetaT);
  const float denP = std::norm(n * C(cosThetaI) + cosThetaT);
  // Both vanish only for an index-matched, loss-free "conductor" at grazing incidence.
  if (denS == 0 || denP == 0) return 1.0f;
  // |a / b|² = |a|² / |b|²: only the reflectances' magnitudes are needed.
  const float rs = std::norm(C(cosThetaI) - n * cosThetaT) / denS;
  const float rp = std::norm(n * C(cosThetaI) - cosThetaT) / denP;
  const float r = 0.5f * (rs + rp);
  return std::isfinite(r) ? std::clamp(r, 0.0f, 1.0f) : 1.0f;
}
}  // namespace

Color3 fresnelConductor(float cosThetaI, const Color3& eta, const Color3& k) {
  cosThetaI = std::clamp(cosThetaI, 0.0f, 1.0f);
  return {conductorChannel(cosThetaI, eta.x(), k.x()), conductorChannel(cosThetaI, eta.y(), k.y()),
          conductorChannel(cosThetaI, eta.z(), k.z())};
}

Color3 fresnelSchlick(float cosThetaI, const Color3& f0) {
  const float m = std::clamp(1.0f - cosThetaI, 0.0f, 1.0f);
  const float m2 = m * m;
  return f0 + (Color3::Ones() - f0) * (m2 * m2 * m);
}

bool refract(const Vector3f& wi, const Vector3f& n, float eta, Vector3f& wt) {
  const float cosThetaI = wi.dot(n);
  const float sin2ThetaT = std::max(0.0f, 1.0f - cosThetaI * cosThetaI) / (eta * eta);
  if (sin2ThetaT >= 1.0f) return false;
  const float cosThetaT = safeSqrt(1.0f - sin2ThetaT);
  wt = (-wi / eta + (cosThetaI / eta - cosThetaT) * n).normalized();
  return true;
}

}  // namespace verity
