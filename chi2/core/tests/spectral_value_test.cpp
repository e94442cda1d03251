// Values with any number of components (issue 40): a spectral Lambertian lobe of four
// wavelengths, its value held in each kind of type a renderer uses (std::array, Eigen's fixed
// and dynamic vectors, std::vector, a spectrum type with a specialised ValueSize), passes; a
// flaw planted in the fourth wavelength alone, beyond RGB's three, is named; values whose sizes
// disagree are a defect with an example, not a crash.
//
// Level: kCorrectChecks checks of two statistical tests each must pass, at a family-wise level
// of 1% with Šidák's correction; the flawed ones use the same level.
#include <gtest/gtest.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/significance.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "lambert_toy.h"

namespace spectral_toy {

// A spectrum type as pbrt writes one: operator[] and a size the compiler cannot see.
inline constexpr int kWavelengths = 4;
struct Spectrum {
  float values[kWavelengths] = {};
  float operator[](int i) const { return values[i]; }
  float& operator[](int i) { return values[i]; }
};

}  // namespace spectral_toy

template <>
struct verity::chi2::ValueSize<spectral_toy::Spectrum>
    : std::integral_constant<int, spectral_toy::kWavelengths> {};

namespace verity::chi2::spectral_value_test {

namespace {

using lambert_toy::Vec3;
using spectral_toy::kWavelengths;

// The correct lobe in five value types.
constexpr int kCorrectChecks = 5;
const double kLevel = sidakLevel(0.01, kStatisticalTestsPerCheck* kCorrectChecks);
constexpr long long kSamples = 200'000;
constexpr std::array<double, kWavelengths> kAlbedo = {0.8, 0.6, 0.4, 0.2};

enum class Flaw {
  None,
  FourthWeight,    // the weight of the fourth wavelength 1% high
  FourthNegative,  // eval of the fourth wavelength negative
  FourthNan,       // eval of the fourth wavelength NaN where wo.x < 0
  ShortEval,       // eval has three entries where wo.y < -0.5 (sized at run time); wi's
                   // mirror direction, where checkBsdf learns the size, has four
};

// The first n entries of a, n < kWavelengths only for a type sized at run time.
template <class Value>
Value make(const std::array<double, kWavelengths>& a, int n = kWavelengths) {
  Value v{};
  if constexpr (ValueAccess<Value>::kComponents == 0) v = Value(n);
  for (int i = 0; i < n; ++i) v[i] = static_cast<std::decay_t<decltype(v[i])>>(a[i]);
  return v;
}

// A Lambertian lobe of albedo kAlbedo per wavelength, cosine-sampled, in the value type Value.
template <class Value>
BsdfModel spectralLambert(Flaw flaw) {
  auto eval = [flaw](const Vec3& wi, const Vec3& wo) {
    std::array<double, kWavelengths> f{};
    if (wi.z > 0 && wo.z > 0)
      for (int i = 0; i < kWavelengths; ++i) f[i] = kAlbedo[i] / std::numbers::pi;
    if (flaw == Flaw::FourthNegative) f[3] = -f[3];
    if (flaw == Flaw::FourthNan && wo.x < 0) f[3] = std::nan("");
    return make<Value>(f, flaw == Flaw::ShortEval && wo.y < -0.5 ? 3 : kWavelengths);
  };
  return bsdfModel<Vec3>(
      [flaw](const Vec3& wi,
             const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, Value>> {
        if (wi.z <= 0) return std::nullopt;
        const Vec3 wo = lambert_toy::cosineHemisphere(u.xy.x, u.xy.y);
        std::array<double, kWavelengths> w = kAlbedo;  // f·cos θ / pdf
        if (flaw == Flaw::FourthWeight) w[3] *= 1.01;
        return SampledDirection<Vec3, Value>{wo, make<Value>(w), lambert_toy::cosinePdf(wo)};
      },
      eval, [](const Vec3&, const Vec3& wo) { return lambert_toy::cosinePdf(wo); });
}

template <class Value>
CheckResult check(Flaw flaw, const std::string& name) {
  BsdfCheckOptions o;
  o.name = "spectral lambert " + name;
  o.significance = kLevel;
  o.samples = kSamples;
  return checkBsdf(spectralLambert<Value>(flaw), Vec3{0.5, 0, 0.8660254}, o);
}

std::string failed(const CheckResult& r) {
  std::string s;
  for (const std::string& f : r.failures()) s += "[" + f + "] ";
  return s + "\n" + r.report();
}

}  // namespace

TEST(SpectralValues, TheNumberOfComponentsIsLearntFromTheType) {
  static_assert(ValueAccess<double>::kComponents == 1);
  static_assert(ValueAccess<std::array<float, 4>>::kComponents == 4);
  static_assert(ValueAccess<Eigen::Array4d>::kComponents == 4);
  // Eigen's size wins over its .x() accessor, which would read three.
  static_assert(ValueAccess<Eigen::Vector4f>::kComponents == 4);
  static_assert(ValueAccess<spectral_toy::Spectrum>::kComponents == 4);
  static_assert(ValueAccess<phong_toy::Rgb>::kComponents == 3);
  static_assert(ValueAccess<std::vector<double>>::kComponents == 0);
  static_assert(ValueAccess<Eigen::VectorXd>::kComponents == 0);
  const Eigen::ArrayXd expected = Eigen::Map<const Eigen::ArrayXd>(kAlbedo.data(), kWavelengths);
  EXPECT_TRUE((ValueAccess<Eigen::Vector4f>::read(make<Eigen::Vector4f>(kAlbedo)) -
               expected.cast<float>().cast<double>())
                  .isZero());
  EXPECT_TRUE(
      (ValueAccess<std::vector<double>>::read(make<std::vector<double>>(kAlbedo)) == expected)
          .all());
  EXPECT_EQ(spectralLambert<std::vector<double>>(Flaw::None).components, 0);
  EXPECT_EQ((spectralLambert<std::array<float, 4>>(Flaw::None).components), 4);
}

TEST(SpectralValues, EachKindOfValueTypePasses) {
  const std::pair<CheckResult, const char*> runs[] = {
      {check<std::array<float, 4>>(Flaw::None, "std::array"), "std::array<float, 4>"},
      {check<Eigen::Vector4f>(Flaw::None, "Eigen::Vector4f"), "Eigen::Vector4f"},
      {check<spectral_toy::Spectrum>(Flaw::None, "Spectrum"), "a specialised ValueSize"},
      {check<std::vector<double>>(Flaw::None, "std::vector"), "std::vector<double>"},
      {check<Eigen::VectorXd>(Flaw::None, "Eigen::VectorXd"), "Eigen::VectorXd"},
  };
  for (const auto& [r, name] : runs) {
    EXPECT_TRUE(r.passed()) << name << ": " << failed(r);
    EXPECT_GT(r.test.valid, 0) << name;
  }
}

TEST(SpectralValues, AWrongWeightInTheFourthWavelengthIsNamed) {
  for (const CheckResult& r : {check<std::array<float, 4>>(Flaw::FourthWeight, "weight fixed"),
                               check<std::vector<double>>(Flaw::FourthWeight, "weight dynamic")}) {
    EXPECT_TRUE(r.failed("weight != eval*cos/pdf")) << failed(r);
    EXPECT_NEAR(r.test.audit.worst(Defect::Weight), 0.01, 1e-6) << failed(r);
    EXPECT_NE(r.test.audit.worstExample(Defect::Weight).find("component 3"), std::string::npos)
        << failed(r);
  }
}

TEST(SpectralValues, ANegativeOrNanFourthWavelengthIsNamed) {
  const CheckResult negative = check<Eigen::Vector4f>(Flaw::FourthNegative, "negative");
  EXPECT_TRUE(negative.failed("negative value")) << failed(negative);
  const CheckResult nan = check<Eigen::VectorXd>(Flaw::FourthNan, "nan");
  EXPECT_TRUE(nan.failed("non-finite value")) << failed(nan);
}

// A value sized at run time whose size changes: a defect with an example, read no further.
TEST(SpectralValues, ValuesOfDifferentSizesAreADefectNotACrash) {
  const CheckResult r = check<std::vector<double>>(Flaw::ShortEval, "short eval");
  EXPECT_TRUE(r.failed("value of the wrong size")) << failed(r);
  EXPECT_NE(r.report().find("eval (0.2546479, 0.1909859, 0.127324) has 3 component(s), the BSDF 4"),
            std::string::npos)
      << failed(r);
}

// A weight of three components (RGB) beside a spectral eval: the weight is the odd one.
TEST(SpectralValues, AWeightOfAnotherFixedSizeIsADefect) {
  using Rgb = std::array<float, 3>;
  const BsdfModel m = bsdfModel<Vec3>(
      [](const Vec3&, const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, Rgb>> {
        const Vec3 wo = lambert_toy::cosineHemisphere(u.xy.x, u.xy.y);
        return SampledDirection<Vec3, Rgb>{wo, Rgb{0.8f, 0.6f, 0.4f}, lambert_toy::cosinePdf(wo)};
      },
      [](const Vec3& wi, const Vec3& wo) {
        return make<std::array<float, 4>>(kAlbedo);  // the lobe's f, without its horizon
      },
      [](const Vec3&, const Vec3& wo) { return lambert_toy::cosinePdf(wo); });
  BsdfCheckOptions o;
  o.name = "spectral lambert rgb weight";
  o.significance = kLevel;
  o.samples = 10'000;
  const CheckResult r = checkBsdf(m, Vec3{0, 0, 1}, o);
  EXPECT_TRUE(r.failed("value of the wrong size")) << failed(r);
  EXPECT_NE(r.report().find("weight (0.8, 0.6, 0.4) has 3 component(s), the BSDF 4"),
            std::string::npos)
      << failed(r);
}

}  // namespace verity::chi2::spectral_value_test
