#include "sampling/warp.h"

namespace verity::warp {

Point2f squareToUniformDiskPolar(const Point2f& u) {
  const float r = std::sqrt(u.x());
  const float phi = 2 * kPi * u.y();
  return {r * std::cos(phi), r * std::sin(phi)};
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
  return {r * std::cos(theta), r * std::sin(theta)};
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
