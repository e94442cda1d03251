#include "sampling/warp.h"

namespace verity::warp {

namespace {
// r·(cos φ, sin φ) with r ≤ 1 can land an ulp outside the unit circle; pull it back (by one
// more ulp, since rounding the quotient may undo it) so that every sample lies in the pdf's
// support, judged exactly.
Point2f onDisk(float r, float phi) {
  const Point2f p(r * std::cos(phi), r * std::sin(phi));
  const double n2 = p.cast<double>().squaredNorm();
  if (n2 <= 1) return p;
  return p * float((1 - 0x1p-23) / std::sqrt(n2));
}
}  // namespace

Point2f squareToUniformDiskPolar(const Point2f& u) {
  return onDisk(std::sqrt(u.x()), 2 * kPi * u.y());
}

Point2f squareToUniformDiskConcentric(const Point2f& u) {
  const Point2f offset = 2.0f * u - Point2f(1, 1);
  if (offset.x() == 0 && offset.y() == 0) return Point2f::Zero();
  float r, theta;
  if (std::fabs(offset.x()) > std::fabs(offset.y())) {
    r = offset.x();
    theta = (kPi / 4) * (offset.y() / offset.x());
  } else {
    r = offset.y();
    theta = kPi / 2 - (kPi / 4) * (offset.x() / offset.y());
  }
  return onDisk(r, theta);
}

Vector3f squareToPowerCosineLobe(const Point2f& u, float exponent) {
  const float oneMinusCos = -std::expm1(std::log(std::max(u.x(), 1e-30f)) / (exponent + 1.0f));
  const float sinTheta = safeSqrt(oneMinusCos * (2.0f - oneMinusCos));
  const float phi = 2 * kPi * u.y();
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), 1.0f - oneMinusCos};
}

Vector3f squareToUniformSphere(const Point2f& u) {
  const float z = 1 - 2 * u.x();
  const float r = safeSqrt(1 - z * z);
  const float phi = 2 * kPi * u.y();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f squareToUniformHemisphere(const Point2f& u) {
  const float z = u.x();
  const float r = safeSqrt(1 - z * z);
  const float phi = 2 * kPi * u.y();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Vector3f squareToCosineHemisphere(const Point2f& u) {
  const Point2f d = squareToUniformDiskConcentric(u);
  return {d.x(), d.y(), safeSqrt(1 - d.squaredNorm())};
}

Vector3f squareToUniformSphericalCap(const Point2f& u, float cosThetaMax) {
  const float z = 1 - u.x() * (1 - cosThetaMax);
  const float r = safeSqrt(1 - z * z);
  const float phi = 2 * kPi * u.y();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

float squareToUniformSphericalCapPdf(const Vector3f& v, float cosThetaMax) {
  if (v.z() < cosThetaMax) return 0;
  return 1.0f / (2 * kPi * (1 - cosThetaMax));
}

Point2f squareToUniformTriangle(const Point2f& u) {
  float b0, b1;
  if (u.x() < u.y()) {
    b0 = u.x() / 2;
    b1 = u.y() - b0;
  } else {
    b1 = u.y() / 2;
    b0 = u.x() - b1;
  }
  return {b0, b1};
}

}  // namespace verity::warp
