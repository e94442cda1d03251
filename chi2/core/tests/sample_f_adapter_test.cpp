// bsdfModelFromSampleF on BSDFs written in pbrt's convention (sample the incident direction wi
// given the outgoing wo; return f and pdf). A Lambertian lobe sampled uniformly cannot tell a
// right mapping from a backwards one: its f and pdf are symmetric in their two directions. The
// toy below is not: its sampling density depends on the sampled direction only (cos³), and its
// f on both directions differently (an albedo set by wo times cos² of wi). So glue that swaps
// wo and wi fails the chi-square test and the sample-pdf and weight checks, and glue that drops
// the cosine, or takes that of the given direction, fails the weight check. The glue that
// docs/checks.md gives for pbrt-v4's BxDFs compiles against their signatures (a stand-in) and
// passes.
//
// Level: kCorrectChecks checks of two statistical tests each must pass, at a family-wise level
// of 1% with Šidák's correction; the backwards glues use the same level.
#include <gtest/gtest.h>
#include <verity/chi2/sample_f_adapter.h>
#include <verity/chi2/significance.h>

#include <cmath>
#include <numbers>

#include "lambert_toy.h"
#include "pbrt_v4_stand_in.h"

// As docs/checks.md tells a pbrt-v4 user to declare it.
template <>
struct verity::chi2::ValueSize<pbrt_v4::SampledSpectrum>
    : std::integral_constant<int, pbrt_v4::NSpectrumSamples> {};

namespace verity::chi2::sample_f_adapter_test {

namespace {

using lambert_toy::Vec3;

// The toy with reciprocity off and on, the Lambertian lobe by the adapter and by swapped glue,
// pbrt-v4's DiffuseBxDF by the documented glue.
constexpr int kCorrectChecks = 5;
const double kLevel = sidakLevel(0.01, kStatisticalTestsPerCheck* kCorrectChecks);
constexpr long long kSamples = 200'000;

using Sample = SampledF<Vec3, double>;

// In pbrt's convention: f(wo, wi) = ρ(wo)·(2/π)·cos²θi with ρ(wo) = 0.5 + 0.4·wo.x, sampled
// by pdf(wo, wi) = (2/π)·cos³θi (cos θi = u^(1/4)), so that f·cos θi / pdf = ρ(wo). Not
// reciprocal: f(wo, wi) ≠ f(wi, wo).
struct TiltedToy {
  static double albedo(const Vec3& wo) { return 0.5 + 0.4 * wo.x; }
  static std::optional<Sample> sampleF(const Vec3& wo, const BsdfUniforms& u) {
    if (wo.z <= 0) return std::nullopt;
    const double cosT = std::pow(u.xy.x, 0.25), sinT = std::sqrt(1 - cosT * cosT);
    const double phi = 2 * std::numbers::pi * u.xy.y;
    const Vec3 wi{sinT * std::cos(phi), sinT * std::sin(phi), cosT};
    return Sample{wi, f(wo, wi), pdf(wo, wi)};
  }
  static double f(const Vec3& wo, const Vec3& wi) {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    return albedo(wo) * 2 / std::numbers::pi * wi.z * wi.z;
  }
  static double pdf(const Vec3& wo, const Vec3& wi) {
    if (wo.z <= 0 || wi.z <= 0) return 0;
    return 2 / std::numbers::pi * wi.z * wi.z * wi.z;
  }
};

// Albedo 0.7, sampled uniformly: f and pdf symmetric in wo and wi.
struct UniformLambert {
  static std::optional<Sample> sampleF(const Vec3& wo, const BsdfUniforms& u) {
    if (wo.z <= 0) return std::nullopt;
    const Vec3 wi = lambert_toy::uniformHemisphere(u.xy.x, u.xy.y);
    return Sample{wi, f(wo, wi), pdf(wo, wi)};
  }
  static double f(const Vec3& wo, const Vec3& wi) {
    return wo.z > 0 && wi.z > 0 ? 0.7 / std::numbers::pi : 0;
  }
  static double pdf(const Vec3& wo, const Vec3& wi) {
    return wo.z > 0 ? lambert_toy::uniformPdf(wi) : 0;
  }
};

template <class Toy>
BsdfModel byAdapter() {
  return bsdfModelFromSampleF<Vec3>(Toy::sampleF, Toy::f, Toy::pdf);
}

enum class Glue {
  Swapped,          // f and pdf called as f(wo, wi) with Verity's names: arguments swapped
  NoCosine,         // weight = f / pdf
  GivenDirections,  // weight = f·|cos| / pdf with the cosine of the given direction
};

// Glue written by hand on bsdfModel, each with one mistake.
template <class Toy>
BsdfModel byHand(Glue glue) {
  return bsdfModel<Vec3>(
      [glue](const Vec3& wi,
             const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, double>> {
        const std::optional<Sample> s = Toy::sampleF(wi, u);
        if (!s) return std::nullopt;
        const double cosine = glue == Glue::NoCosine          ? 1
                              : glue == Glue::GivenDirections ? std::fabs(wi.z)
                                                              : std::fabs(s->wi.z);
        return SampledDirection<Vec3, double>{s->wi, s->f * cosine / s->pdf, s->pdf};
      },
      [glue](const Vec3& wi, const Vec3& wo) {
        return glue == Glue::Swapped ? Toy::f(wo, wi) : Toy::f(wi, wo);
      },
      [glue](const Vec3& wi, const Vec3& wo) {
        return glue == Glue::Swapped ? Toy::pdf(wo, wi) : Toy::pdf(wi, wo);
      });
}

BsdfCheckOptions options(const std::string& name) {
  BsdfCheckOptions o;
  o.name = "sample_f " + name;
  o.significance = kLevel;
  o.samples = kSamples;
  return o;
}

// At 40° from the normal, towards +x, where the toy's albedo is 0.76.
CheckResult check(const BsdfModel& m, const std::string& name, bool reciprocity = false) {
  BsdfCheckOptions o = options(name);
  // The toy is not reciprocal on purpose; its reciprocity is the test's own subject.
  o.checkReciprocity = reciprocity;
  const double t = 40 * std::numbers::pi / 180;
  return checkBsdf(m, Vec3{std::sin(t), 0, std::cos(t)}, o);
}

std::string failed(const CheckResult& r) {
  std::string s;
  for (const std::string& f : r.failures()) s += "[" + f + "] ";
  return s + "\n" + r.report();
}

}  // namespace

TEST(SampleFAdapter, TheAsymmetricToyPassesThroughTheAdapter) {
  const CheckResult r = check(byAdapter<TiltedToy>(), "toy by the adapter");
  EXPECT_TRUE(r.passed()) << failed(r);
  EXPECT_EQ(r.test.valid, r.test.samples);
  // Checked for reciprocity, the toy fails that alone: the distribution is right.
  const CheckResult withReciprocity =
      check(byAdapter<TiltedToy>(), "toy by the adapter, reciprocity", true);
  EXPECT_EQ(withReciprocity.failures(), std::vector<std::string>{"reciprocity"})
      << failed(withReciprocity);
}

TEST(SampleFAdapter, SwappedGlueFailsOnTheToy) {
  const CheckResult r = check(byHand<TiltedToy>(Glue::Swapped), "toy swapped");
  EXPECT_TRUE(r.failed("chi-square")) << failed(r);
  EXPECT_TRUE(r.failed("sample pdf != pdf()")) << failed(r);
  EXPECT_TRUE(r.failed("weight != eval*cos/pdf")) << failed(r);
}

TEST(SampleFAdapter, GlueWithoutTheSampledCosineFailsOnTheToy) {
  for (Glue glue : {Glue::NoCosine, Glue::GivenDirections}) {
    const CheckResult r =
        check(byHand<TiltedToy>(glue), glue == Glue::NoCosine ? "toy no cosine" : "toy cosine");
    EXPECT_TRUE(r.failed("weight != eval*cos/pdf")) << failed(r);
  }
}

// Why the toy: a Lambertian lobe sampled uniformly passes the right mapping and the swapped
// one alike.
TEST(SampleFAdapter, ASymmetricLobeCannotTellTheMappingsApart) {
  const CheckResult right = check(byAdapter<UniformLambert>(), "lambert by the adapter", true);
  EXPECT_TRUE(right.passed()) << failed(right);
  const CheckResult swapped = check(byHand<UniformLambert>(Glue::Swapped), "lambert swapped", true);
  EXPECT_TRUE(swapped.passed()) << failed(swapped);
}

// docs/checks.md's glue for pbrt-v4, as written there, on the stand-in's DiffuseBxDF (float,
// four wavelengths): it compiles where the sample flags are a parameter and a Point2f of
// doubles would narrow (the glue once wrote {u.xy.x, u.xy.y}), and the BxDF passes.
TEST(SampleFAdapter, TheGlueForPbrtV4CompilesAndPasses) {
  using namespace pbrt_v4;
  const DiffuseBxDF bxdf(SampledSpectrum(0.9f, 0.7f, 0.5f, 0.3f));
  // From docs/checks.md:
  const TransportMode mode = TransportMode::Radiance;
  const BxDFReflTransFlags flags = BxDFReflTransFlags::All;
  chi2::BsdfModel model = chi2::bsdfModelFromSampleF<Vector3f>(
      [&](const Vector3f& wo,
          const chi2::BsdfUniforms& u) -> std::optional<chi2::SampledF<Vector3f, SampledSpectrum>> {
        const pstd::optional<BSDFSample> s =
            bxdf.Sample_f(wo, Float(u.lobe), Point2f(Float(u.xy.x), Float(u.xy.y)), mode, flags);
        if (!s) return std::nullopt;
        return chi2::SampledF<Vector3f, SampledSpectrum>{s->wi, s->f, s->pdf, s->IsSpecular()};
      },
      [&](const Vector3f& wo, const Vector3f& wi) { return bxdf.f(wo, wi, mode); },
      [&](const Vector3f& wo, const Vector3f& wi) { return bxdf.PDF(wo, wi, mode, flags); });
  // (end of the documented glue)
  EXPECT_EQ(model.components, NSpectrumSamples);
  const CheckResult r = checkBsdf(model, Vector3f(0.5f, 0, 0.866f), options("pbrt-v4 diffuse"));
  EXPECT_EQ(r.verdict(), Verdict::Passed) << failed(r);
}

}  // namespace verity::chi2::sample_f_adapter_test
