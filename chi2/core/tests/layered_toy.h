// A layered BSDF as a renderer's random walk would give it, in its own types: a Lambertian
// whose eval and sample weight are unbiased random estimates. A Flaw plants one of the errors
// the stochastic mode must find. Values are RGB or four components, as pbrt-v4's
// SampledSpectrum (read through [i], their number given by a ValueSize specialisation).
#pragma once

#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/sampling_check.h>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <string>

#include "phong_toy.h"

namespace layered_toy {

struct Spectrum4 {
  std::array<float, 4> values{};
  float operator[](int i) const { return values[i]; }
};

}  // namespace layered_toy

template <>
struct verity::chi2::ValueSize<layered_toy::Spectrum4> : std::integral_constant<int, 4> {};

namespace layered_toy {

using phong_toy::Rgb;
using phong_toy::Vec3;
using verity::chi2::BsdfModel;
using verity::chi2::BsdfUniforms;
using verity::chi2::SampledDirection;

enum class Flaw { None, EvalLow, WeightLow, WeightSkewed, FourthEvalLow };

// The toy's albedo times f: (0.8, 0.6, 0.4) in RGB, (0.8, 0.6, 0.4, 0.7·fourth) in four
// components.
template <class Value>
Value tinted(double f, double fourth);
template <>
inline Rgb tinted<Rgb>(double f, double) {
  return {float(0.8 * f), float(0.6 * f), float(0.4 * f)};
}
template <>
inline Spectrum4 tinted<Spectrum4>(double f, double fourth) {
  return {{float(0.8 * f), float(0.6 * f), float(0.4 * f), float(0.7 * f * fourth)}};
}

// A Lambertian of albedo `scale` times the tint whose eval and sample weight are each
// multiplied by a random factor uniform in [0.5, 1.5) (mean 1) from its own generator, as a
// layered BSDF's random walk would return them; a Flaw scales one of them by 0.98
// (FourthEvalLow: eval's fourth component alone), or the weight by 1.1 where wo.y > 0 and 0.9
// where wo.y < 0 (the same total albedo for wi in the xz plane).
template <class Value>
class LayeredToy {
 public:
  LayeredToy(Flaw flaw, uint64_t seed, double scale = 1)
      : flaw_(flaw), scale_(scale), rng_(std::make_shared<std::mt19937_64>(seed)) {}

  Value eval(const Vec3& wi, const Vec3& wo) const {
    if (wi.z <= 0 || wo.z <= 0) return {};
    const double f = scale_ * factor() / std::numbers::pi * (flaw_ == Flaw::EvalLow ? 0.98 : 1);
    return tinted<Value>(f, flaw_ == Flaw::FourthEvalLow ? 0.98 : 1);
  }
  std::optional<SampledDirection<Vec3, Value>> sample(const Vec3& wi, double u0, double u1) const {
    if (wi.z <= 0) return std::nullopt;
    const double r = std::sqrt(u0), phi = 2 * std::numbers::pi * u1;
    const Vec3 wo{r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u0))};
    if (wo.z <= 0) return std::nullopt;
    double w = scale_ * factor() * (flaw_ == Flaw::WeightLow ? 0.98 : 1);
    if (flaw_ == Flaw::WeightSkewed) w *= wo.y > 0 ? 1.1 : 0.9;
    return SampledDirection<Vec3, Value>{wo, tinted<Value>(w, 1), 0};
  }

 private:
  double factor() const { return 0.5 + std::uniform_real_distribution<double>()(*rng_); }

  Flaw flaw_;
  double scale_;
  std::shared_ptr<std::mt19937_64> rng_;  // one generator for the model's copies
};

// Its generator seeded from `name`.
template <class Value = Rgb>
BsdfModel layeredModel(Flaw flaw, const std::string& name, double scale = 1) {
  const LayeredToy<Value> toy(flaw, verity::chi2::seedFromName(name + " toy"), scale);
  // No pdf: the mode does not use one.
  return verity::chi2::bsdfModel<Vec3>(
      [toy](const Vec3& wi, const BsdfUniforms& u) { return toy.sample(wi, u.xy.x, u.xy.y); },
      [toy](const Vec3& wi, const Vec3& wo) { return toy.eval(wi, wo); },
      [](const Vec3&, const Vec3&) { return 0.0; });
}

}  // namespace layered_toy
