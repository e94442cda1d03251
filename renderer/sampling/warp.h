// Maps from uniform samples on [0,1)² to other domains, each with its density.
#pragma once

#include "core/math.h"

namespace verity::warp {

// Disk of radius 1: the polar map (r = √u, φ = 2πv) and Shirley–Chiu's concentric map
// (Shirley and Chiu 1997, "A Low Distortion Map Between Disk and Square").
Point2f squareToUniformDiskPolar(const Point2f& u);
Point2f squareToUniformDiskConcentric(const Point2f& u);
// The lobe (n+1)/(2π)·cos^n θ about +z (Phong's lobe, Blinn–Phong's half-vector): cos θ =
// u^(1/(n+1)), with 1 − cos θ taken through expm1 so that sharp lobes keep sin θ's precision.
Vector3f squareToPowerCosineLobe(const Point2f& u, float exponent);
inline float squareToUniformDiskPdf(const Point2f& p) {
  return p.squaredNorm() <= 1 ? kInvPi : 0;
}

Vector3f squareToUniformSphere(const Point2f& u);
inline float squareToUniformSpherePdf(const Vector3f&) {
  return kInv4Pi;
}

Vector3f squareToUniformHemisphere(const Point2f& u);
inline float squareToUniformHemispherePdf(const Vector3f& v) {
  return v.z() >= 0 ? kInv2Pi : 0;
}

// Density cos θ / π (Malley's method through the concentric disk map).
Vector3f squareToCosineHemisphere(const Point2f& u);
inline float squareToCosineHemispherePdf(const Vector3f& v) {
  return v.z() > 0 ? v.z() * kInvPi : 0;
}

// Uniform over the cap of directions within θmax of +z, given cos θmax.
Vector3f squareToUniformSphericalCap(const Point2f& u, float cosThetaMax);
float squareToUniformSphericalCapPdf(const Vector3f& v, float cosThetaMax);

// Barycentric coordinates (b0, b1), uniform over a triangle (Heitz 2019, "A Low-Distortion
// Map Between Triangle and Square").
Point2f squareToUniformTriangle(const Point2f& u);
inline float squareToUniformTrianglePdf(const Point2f& b) {
  return (b.x() >= 0 && b.y() >= 0 && b.x() + b.y() <= 1) ? 2.0f : 0.0f;
}

}  // namespace verity::warp
