// A toy BSDF written as another renderer would write it, in its own types and with no
// Verity type: the modified Phong lobe (Lafortune & Willems 1994, "Using the modified Phong
// reflectance model for physically based rendering"), f = (n+2)/(2π)·cosⁿα about the mirror
// direction, sampled exactly by pdf = (n+1)/(2π)·cosⁿα; samples below the horizon fail. A
// Flaw plants one of the mistakes the adapters must name.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>

namespace phong_toy {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

struct Rgb {
  float r = 0, g = 0, b = 0;
};

struct Sample {
  Vec3 wo;
  Rgb weight;
  float pdf = 0;
};

enum class Flaw {
  None,
  PdfNormalisation,  // pdf by (n+2)/(2π), the BSDF's constant, in pdf() and sample()
  Weight,            // weight = cos θo, the ratio (n+2)/(n+1) forgotten
  NonReciprocal,     // f scaled by (1 + wo.z)
  UnclampedLobe,     // cosⁿα with cos α < 0 and a fractional n: NaN away from the lobe
  SamplePdf,         // sample() reports the density of exponent n+1
};

class Phong {
 public:
  Phong(double exponent, Flaw flaw) : n_(exponent), flaw_(flaw) {}

  Rgb eval(const Vec3& wi, const Vec3& wo) const {
    if (wi.z <= 0 || wo.z <= 0) return {};
    double f = (n_ + 2) / (2 * std::numbers::pi) * lobe(wi, wo, n_);
    if (flaw_ == Flaw::NonReciprocal) f *= 1 + wo.z;
    // A grey lobe with a red tint, so that all three channels are compared.
    return {float(f), float(0.5 * f), float(0.25 * f)};
  }

  double pdf(const Vec3& wi, const Vec3& wo) const { return density(wi, wo, n_); }

  std::optional<Sample> sample(const Vec3& wi, double u0, double u1) const {
    if (wi.z <= 0) return std::nullopt;
    // cos α = u0^(1/(n+1)), φ uniform, about the mirror direction r.
    const double cosA = std::pow(u0, 1 / (n_ + 1)), sinA = std::sqrt(1 - cosA * cosA);
    const double phi = 2 * std::numbers::pi * u1;
    const Vec3 r = mirror(wi);
    Vec3 s, t;
    basis(r, s, t);
    const double a = sinA * std::cos(phi), b = sinA * std::sin(phi);
    const Vec3 wo{a * s.x + b * t.x + cosA * r.x, a * s.y + b * t.y + cosA * r.y,
                  a * s.z + b * t.z + cosA * r.z};
    if (wo.z <= 0) return std::nullopt;
    Sample out;
    out.wo = wo;
    out.pdf = float(flaw_ == Flaw::SamplePdf ? density(wi, wo, n_ + 1) : density(wi, wo, n_));
    const Rgb f = eval(wi, wo);
    const double scale = flaw_ == Flaw::Weight ? wo.z / f.r : wo.z / out.pdf;
    out.weight = {float(f.r * scale), float(f.g * scale), float(f.b * scale)};
    return out;
  }

 private:
  static Vec3 mirror(const Vec3& w) { return {-w.x, -w.y, w.z}; }
  // Duff et al. 2017, "Building an Orthonormal Basis, Revisited".
  static void basis(const Vec3& n, Vec3& s, Vec3& t) {
    const double sign = std::copysign(1.0, n.z), a = -1 / (sign + n.z), b = n.x * n.y * a;
    s = {1 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    t = {b, sign + n.y * n.y * a, -n.y};
  }
  double lobe(const Vec3& wi, const Vec3& wo, double n) const {
    const double c = dot(mirror(wi), wo);
    if (flaw_ == Flaw::UnclampedLobe) return std::pow(c, n);
    return c > 0 ? std::pow(c, n) : 0;
  }
  double density(const Vec3& wi, const Vec3& wo, double n) const {
    if (wi.z <= 0 || wo.z <= 0) return 0;
    const double norm = flaw_ == Flaw::PdfNormalisation ? n + 2 : n + 1;
    return norm / (2 * std::numbers::pi) * lobe(wi, wo, n);
  }

  double n_;
  Flaw flaw_;
};

}  // namespace phong_toy
