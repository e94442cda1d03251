// A stand-in for the pbrt-v4 types a BxDF's interface uses, with their signatures (Pharr,
// Jakob & Humphreys, "Physically Based Rendering", 4th ed., §9.1; pbrt-v4's base/bxdf.h):
// Float is float, a Point2f is built from two Floats (so brace-initialising it from doubles
// narrows), a SampledSpectrum holds NSpectrumSamples = 4 values read through [i], and every
// BxDF takes the transport mode and the sample flags,
//   Sample_f(wo, uc, u, mode, sampleFlags = All) -> pstd::optional<BSDFSample>
//   f(wo, wi, mode) -> SampledSpectrum
//   PDF(wo, wi, mode, sampleFlags = All) -> Float
// as ConductorBxDF and DiffuseBxDF do. The BxDF here is pbrt-v4's DiffuseBxDF: R/π, sampled
// by cos θ/π with Malley's method.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace pbrt_v4 {

using Float = float;
inline constexpr int NSpectrumSamples = 4;
inline constexpr Float InvPi = Float(1 / std::numbers::pi);

struct Vector3f {
  Float x = 0, y = 0, z = 0;
  Vector3f() = default;
  Vector3f(Float x, Float y, Float z) : x(x), y(y), z(z) {}
};

struct Point2f {
  Float x = 0, y = 0;
  Point2f(Float x, Float y) : x(x), y(y) {}
};

class SampledSpectrum {
 public:
  explicit SampledSpectrum(Float c) { values_.fill(c); }
  SampledSpectrum(Float a, Float b, Float c, Float d) : values_{a, b, c, d} {}
  Float operator[](int i) const { return values_[i]; }
  SampledSpectrum operator*(Float s) const {
    return {values_[0] * s, values_[1] * s, values_[2] * s, values_[3] * s};
  }

 private:
  std::array<Float, NSpectrumSamples> values_;
};

enum class TransportMode { Radiance, Importance };
enum class BxDFReflTransFlags { Unset = 0, Reflection = 1, Transmission = 2, All = 3 };
inline bool operator&(BxDFReflTransFlags a, BxDFReflTransFlags b) {
  return (int(a) & int(b)) != 0;
}

namespace pstd {
template <class T>
using optional = std::optional<T>;
}  // namespace pstd

struct BSDFSample {
  SampledSpectrum f{0};
  Vector3f wi;
  Float pdf = 0;
  bool specular = false;
  bool IsSpecular() const { return specular; }
};

class DiffuseBxDF {
 public:
  explicit DiffuseBxDF(SampledSpectrum R) : R_(R) {}

  SampledSpectrum f(Vector3f wo, Vector3f wi, TransportMode) const {
    return sameHemisphere(wo, wi) ? R_ * InvPi : SampledSpectrum(0);
  }
  pstd::optional<BSDFSample> Sample_f(
      Vector3f wo, Float, Point2f u, TransportMode mode,
      BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection)) return {};
    const Float r = std::sqrt(u.x), phi = Float(2 * std::numbers::pi) * u.y;
    Vector3f wi(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(Float(0), 1 - u.x)));
    if (wo.z < 0) wi.z = -wi.z;
    const Float pdf = std::abs(wi.z) * InvPi;
    if (pdf == 0) return {};
    return BSDFSample{f(wo, wi, mode), wi, pdf};
  }
  Float PDF(Vector3f wo, Vector3f wi, TransportMode,
            BxDFReflTransFlags sampleFlags = BxDFReflTransFlags::All) const {
    if (!(sampleFlags & BxDFReflTransFlags::Reflection) || !sameHemisphere(wo, wi)) return 0;
    return std::abs(wi.z) * InvPi;
  }

 private:
  static bool sameHemisphere(Vector3f a, Vector3f b) { return a.z * b.z > 0; }
  SampledSpectrum R_;
};

}  // namespace pbrt_v4
