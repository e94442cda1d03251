// Delta lobes through the BSDF adapter, on toys in their own types: a smooth mirror, smooth
// glass (Fresnel-chosen reflection or refraction, pbrt's radiance scaling 1/η²), thin glass
// (pbrt's ThinDielectric) and a mirror over a diffuse base pass, and are PASSED, never
// INCONCLUSIVE; a refraction with the wrong index, a tilted mirror and a refraction that
// forgets 1/η² against its stated albedo fail; a stated albedo of a lobe drawn too rarely is
// untested, and says so.
//
// Level: the correct subjects are kCorrectChecks checks holding kCorrectTests statistical
// tests (two per check and one per stated share or albedo), at a family-wise level of 1% with
// Šidák's correction; the broken ones use the same per-test level. Their defects are found
// with certainty: a direction is checked per sample, and the missing 1/η² moves the
// refraction's albedo by 0.53, some 500 standard errors at 10⁵ samples.
#include <gtest/gtest.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/power.h>
#include <verity/chi2/significance.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "glass_toy.h"
#include "phong_toy.h"

namespace verity::chi2::delta_check_test {

namespace {

using glass_toy::deltaModel;
using glass_toy::expectGlass;
using glass_toy::fresnel;
using glass_toy::Glass;
using glass_toy::glassModel;
using glass_toy::mirror;
using glass_toy::Sample;
using phong_toy::Vec3;

enum class Flaw { None, TiltedMirror };

// A tinted mirror (weight 0.9, 0.8, 0.7), or one tilted by 0.01 rad about y.
struct Mirror {
  Flaw flaw = Flaw::None;

  std::optional<SampledDirection<Vec3, phong_toy::Rgb>> sample(const Vec3& wi) const {
    Vec3 wo = mirror(wi);
    if (flaw == Flaw::TiltedMirror) {
      const double c = std::cos(0.01), s = std::sin(0.01);
      wo = {c * wo.x + s * wo.z, wo.y, -s * wo.x + c * wo.z};
    }
    return SampledDirection<Vec3, phong_toy::Rgb>{wo, {0.9f, 0.8f, 0.7f}, 1, true};
  }
  BsdfModel model() const {
    return bsdfModel<Vec3>(
        [m = *this](const Vec3& wi, const BsdfUniforms&) { return m.sample(wi); },
        [](const Vec3&, const Vec3&) { return phong_toy::Rgb{}; },
        [](const Vec3&, const Vec3&) { return 0.0; });
  }
};

// pbrt-v4's ThinDielectric: the inter-reflections summed into R, the rest straight through.
struct ThinGlass {
  double eta;

  double reflectance(const Vec3& wi) const {
    double r = fresnel(std::fabs(wi.z), eta);
    const double t = 1 - r;
    if (r < 1) r += t * t * r / (1 - r * r);
    return r;
  }
  std::optional<Sample> sample(const Vec3& wi, double u) const {
    const double r = reflectance(wi);
    if (u < r) return Sample{mirror(wi), 1, r};
    return Sample{{-wi.x, -wi.y, -wi.z}, 1, 1 - r};
  }
};

// A clear coat as a fixed quarter of mirror over a diffuse base of albedo 0.5: the mirror is
// chosen with probability 1/4 (weight 1), the base's cosine-weighted lobe otherwise.
struct CoatedDiffuse {
  static constexpr double kCoat = 0.25, kBase = 0.5;

  std::optional<Sample> sample(const Vec3& wi, double lobe, double u0, double u1) const {
    if (wi.z <= 0) return std::nullopt;
    if (lobe < kCoat) return Sample{mirror(wi), 1, kCoat};
    const double r = std::sqrt(u0), phi = 2 * std::numbers::pi * u1;
    const Vec3 wo{r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u0))};
    if (wo.z <= 0) return std::nullopt;
    return Sample{wo, kBase, pdf(wi, wo), false};
  }
  double eval(const Vec3& wi, const Vec3& wo) const {
    return wi.z > 0 && wo.z > 0 ? (1 - kCoat) * kBase / std::numbers::pi : 0;
  }
  double pdf(const Vec3& wi, const Vec3& wo) const {
    return wi.z > 0 && wo.z > 0 ? (1 - kCoat) * wo.z / std::numbers::pi : 0;
  }
};

Vec3 incidence(double degrees) {
  const double t = degrees * std::numbers::pi / 180;
  return {std::sin(t), 0, std::cos(t)};
}

// Correct checks: mirror, spectral mirror, glass from outside and inside, thin glass, coated
// diffuse, mirror and uniform sphere under a target; their tests: 2 each, and 1 + 4 + 4 + 4 + 2
// stated shares and albedos.
constexpr int kCorrectChecks = 8;
constexpr int kCorrectTests = kStatisticalTestsPerCheck * kCorrectChecks + 15;
const double kLevel = sidakLevel(0.01, kCorrectTests);
constexpr long long kSamples = 100'000;

BsdfCheckOptions options(const std::string& name) {
  BsdfCheckOptions o;
  o.name = "delta " + name;
  o.significance = kLevel;
  o.samples = kSamples;
  return o;
}

std::string failed(const CheckResult& r) {
  std::string s;
  for (const std::string& f : r.failures()) s += "[" + f + "] ";
  return s + "\n" + r.report();
}

}  // namespace

// A mirror with no expectation stated: every sample's direction and weight are checked, so it
// is PASSED, where the histogram alone had nothing to check.
TEST(DeltaLobes, SmoothMirrorPasses) {
  const CheckResult r = checkBsdf(Mirror{}.model(), incidence(30), options("mirror"));
  EXPECT_EQ(r.verdict(), Verdict::Passed) << failed(r);
  EXPECT_EQ(r.test.valid, 0);
  EXPECT_EQ(r.delta.lobes[int(DeltaLobe::Reflection)].count, kSamples);
  EXPECT_NEAR(r.delta.lobes[int(DeltaLobe::Reflection)].albedo[1], 0.8, 1e-7);
}

// Every sample a delta lobe: the histogram's chi-square test did not run, so the check states
// no power for it (it once read "a 0% density error ... would have been found with 0%
// probability"), while the delta lobes' own checks pass it.
TEST(DeltaLobes, AllDeltaSamplesStateNoChiSquarePower) {
  const CheckResult r = checkBsdf(Mirror{}.model(), incidence(30), options("mirror"));
  ASSERT_FALSE(r.test.chiSquareRan()) << r.report();
  const std::string power = r.test.chiSquarePower.describe();
  EXPECT_NE(power.find("did not run"), std::string::npos) << power;
  EXPECT_EQ(power.find('%'), std::string::npos) << power;
  EXPECT_EQ(r.report().find("0% density error"), std::string::npos) << r.report();
  EXPECT_TRUE(std::isinf(r.test.chiSquarePower.densityError(kStatedMass))) << power;
}

// Under a target, a mirror's histogram claims nothing and draws only what meets a stray sample
// (460 for 2% over 1/4 of the mass); its delta lobes get what the target needs of a histogram
// of the same cells holding the whole mass: the samples the same check draws for a density
// spread over the whole sphere (every cell holds mass: 2,047 dof). They once got the 460.
TEST(DeltaLobes, UnderATargetTheDeltaLobesGetWhatAFullHistogramWouldDraw) {
  BsdfCheckOptions o = options("mirror target");
  o.detect = DetectionTarget{0.02, 0.25, 0.9};
  const CheckResult mirror = checkBsdf(Mirror{}.model(), incidence(30), o);
  EXPECT_EQ(mirror.verdict(), Verdict::Passed) << failed(mirror);
  EXPECT_EQ(mirror.test.samples, 460);
  const double albedo = 0.5;
  const BsdfModel sphere = bsdfModel<Vec3>(
      [&](const Vec3&, const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, double>> {
        const double z = 1 - 2 * u.xy.x, r = std::sqrt(std::max(0.0, 1 - z * z));
        const double phi = 2 * std::numbers::pi * u.xy.y;
        return SampledDirection<Vec3, double>{Vec3{r * std::cos(phi), r * std::sin(phi), z},
                                              albedo * std::fabs(z), 1 / (4 * std::numbers::pi)};
      },
      [&](const Vec3&, const Vec3&) { return albedo / (4 * std::numbers::pi); },
      [](const Vec3&, const Vec3&) { return 1 / (4 * std::numbers::pi); });
  o.name = "uniform sphere target";
  const CheckResult full = checkBsdf(sphere, incidence(30), o);
  ASSERT_EQ(full.test.chiSquare.dof, full.test.domain.cells() - 1) << full.report();
  EXPECT_EQ(mirror.delta.samples, full.test.samples);
}

// A spectral mirror: four wavelengths, each with its own reflectance, held to a stated albedo
// per wavelength. (Its weights once went into three-component sums.)
TEST(DeltaLobes, SpectralMirrorIsCheckedPerWavelength) {
  const auto model = [](double last) {
    return bsdfModel<Vec3>(
        [last](const Vec3& wi, const BsdfUniforms&) {
          return std::optional(SampledDirection<Vec3, std::array<double, 4>>{
              mirror(wi), {0.9, 0.8, 0.7, last}, 1, true});
        },
        [](const Vec3&, const Vec3&) { return std::array<double, 4>{}; },
        [](const Vec3&, const Vec3&) { return 0.0; });
  };
  BsdfCheckOptions o = options("spectral mirror");
  Eigen::ArrayXd albedo(4);
  albedo << 0.9, 0.8, 0.7, 0.6;
  o.delta.expect(DeltaLobe::Reflection).albedo = albedo;
  const CheckResult right = checkBsdf(model(0.6), incidence(30), o);
  EXPECT_EQ(right.verdict(), Verdict::Passed) << failed(right);
  ASSERT_EQ(right.delta.lobes[int(DeltaLobe::Reflection)].albedo.size(), 4);
  EXPECT_NEAR(right.delta.lobes[int(DeltaLobe::Reflection)].albedo[3], 0.6, 1e-12);
  const CheckResult wrong = checkBsdf(model(0.5), incidence(30), o);
  EXPECT_TRUE(wrong.failed("delta albedo")) << failed(wrong);
}

TEST(DeltaLobes, SmoothGlassPassesFromBothSides) {
  for (double degrees : {45.0, 150.0}) {
    const Vec3 wi = incidence(degrees);
    BsdfCheckOptions o = options("glass " + std::to_string(degrees));
    expectGlass(o, wi, 1.5);
    const CheckResult r = checkBsdf(glassModel({1.5}), wi, o);
    EXPECT_EQ(r.verdict(), Verdict::Passed) << failed(r);
    EXPECT_GT(r.delta.lobes[int(DeltaLobe::Refraction)].count, 0) << failed(r);
  }
}

TEST(DeltaLobes, ThinGlassPasses) {
  const ThinGlass g{1.5};
  const Vec3 wi = incidence(60);
  BsdfCheckOptions o = options("thin glass");
  const double r = g.reflectance(wi);
  o.delta.expect(DeltaLobe::Reflection) = {r, Eigen::ArrayXd::Constant(1, r)};
  o.delta.expect(DeltaLobe::PassThrough) = {1 - r, Eigen::ArrayXd::Constant(1, 1 - r)};
  const CheckResult c = checkBsdf(
      deltaModel([g](const Vec3& wi, const BsdfUniforms& u) { return g.sample(wi, u.lobe); }), wi,
      o);
  EXPECT_EQ(c.verdict(), Verdict::Passed) << failed(c);
}

// The histogram checks the diffuse base (its ∫pdf is 3/4, the chance of not choosing the
// coat), the delta checks the coat.
TEST(DeltaLobes, MixedBsdfHistogramsItsDiffusePartAndChecksItsDeltaPart) {
  const CoatedDiffuse c;
  const BsdfModel m = bsdfModel<Vec3>(
      [c](const Vec3& wi, const BsdfUniforms& u) { return c.sample(wi, u.lobe, u.xy.x, u.xy.y); },
      [c](const Vec3& wi, const Vec3& wo) { return c.eval(wi, wo); },
      [c](const Vec3& wi, const Vec3& wo) { return c.pdf(wi, wo); });
  BsdfCheckOptions o = options("coated diffuse");
  o.delta.expect(DeltaLobe::Reflection) = {CoatedDiffuse::kCoat,
                                           Eigen::ArrayXd::Constant(1, CoatedDiffuse::kCoat)};
  const CheckResult r = checkBsdf(m, incidence(40), o);
  EXPECT_EQ(r.verdict(), Verdict::Passed) << failed(r);
  EXPECT_FALSE(r.test.chiSquare.degenerate) << failed(r);
  EXPECT_GT(r.test.valid, kSamples / 2) << failed(r);
  EXPECT_GT(r.delta.deltaSamples, kSamples / 5) << failed(r);
}

TEST(DeltaLobes, RefractionForAnotherIndexIsRejected) {
  const Vec3 wi = incidence(45);
  BsdfCheckOptions o = options("glass 1.33 stated 1.5");
  o.delta.eta = 1.5;
  const CheckResult r = checkBsdf(glassModel({1.33}), wi, o);
  EXPECT_EQ(r.verdict(), Verdict::Failed) << failed(r);
  EXPECT_TRUE(r.failed("delta direction")) << failed(r);
}

// Without η stated, a refraction is in no accepted direction: the report says to state it.
TEST(DeltaLobes, RefractionWithoutAStatedIndexIsRejected) {
  const CheckResult r = checkBsdf(glassModel({1.5}), incidence(45), options("glass no eta"));
  EXPECT_TRUE(r.failed("delta direction")) << failed(r);
  EXPECT_NE(r.report().find("DeltaCheckOptions::eta"), std::string::npos) << r.report();
}

TEST(DeltaLobes, TiltedMirrorIsRejected) {
  const CheckResult r =
      checkBsdf(Mirror{Flaw::TiltedMirror}.model(), incidence(30), options("tilted mirror"));
  EXPECT_EQ(r.verdict(), Verdict::Failed) << failed(r);
  EXPECT_TRUE(r.failed("delta direction")) << failed(r);
}

// Right directions and shares; the refraction's weight lacks 1/η².
TEST(DeltaLobes, RefractionWithoutRadianceScalingFailsItsStatedAlbedo) {
  const Vec3 wi = incidence(45);
  BsdfCheckOptions o = options("glass without 1/eta^2");
  expectGlass(o, wi, 1.5);
  const CheckResult r = checkBsdf(glassModel({1.5, true}), wi, o);
  // One verdict: the histogram's part (every sample a delta lobe) claims none of its own.
  EXPECT_EQ(r.report().find("PASSED"), std::string::npos) << r.report();
  EXPECT_EQ(r.verdict(), Verdict::Failed) << failed(r);
  EXPECT_FALSE(r.passed());
  EXPECT_TRUE(r.failed("delta albedo")) << failed(r);
  EXPECT_FALSE(r.failed("delta direction")) << failed(r);
  EXPECT_FALSE(r.failed("delta share")) << failed(r);
}

// A lobe that no draw samples has an albedo interval of width 0, so any stated albedo above 0
// failed, however small (a mirror's pass-through of 1e-9, which 10⁵ draws could never see).
// Too few draws of a lobe leave its stated albedo untested and the check INCONCLUSIVE, saying
// why; an albedo of exactly 0 for a lobe never drawn is what was seen, and passes.
TEST(DeltaLobes, AnAlbedoOfALobeNeverDrawnIsUntestedNotFailed) {
  const Vec3 wi = incidence(30);
  BsdfCheckOptions o = options("mirror with a pass-through of 1e-9");
  o.delta.expect(DeltaLobe::PassThrough).albedo = Eigen::ArrayXd::Constant(1, 1e-9);
  CheckResult r = checkBsdf(Mirror{}.model(), wi, o);
  EXPECT_EQ(r.verdict(), Verdict::Inconclusive) << failed(r);
  EXPECT_FALSE(r.failed("delta albedo")) << failed(r);
  EXPECT_NE(r.inconclusiveReason().find("pass-through lobe was drawn 0 times"), std::string::npos)
      << r.inconclusiveReason();
  EXPECT_NE(r.report().find("[untested] pass-through"), std::string::npos) << r.report();

  o.delta.expect(DeltaLobe::PassThrough).albedo = Eigen::ArrayXd::Constant(1, 0.0);
  r = checkBsdf(Mirror{}.model(), wi, o);
  EXPECT_EQ(r.verdict(), Verdict::Passed) << failed(r);
}

// Glass of index 1.0202 reflects 10⁻⁴ at normal incidence: about 10 of 10⁵ draws, too few for
// the reflection's albedo, while the shares' exact intervals still test both lobes.
TEST(DeltaLobes, AnAlbedoOfALobeDrawnAFewTimesIsUntested) {
  const Vec3 wi = incidence(0);
  BsdfCheckOptions o = options("glass 1.0202");
  expectGlass(o, wi, 1.0202);
  const CheckResult r = checkBsdf(glassModel({1.0202}), wi, o);
  const long long drawn = r.delta.lobes[int(DeltaLobe::Reflection)].count;
  EXPECT_GT(drawn, 0);
  EXPECT_LT(drawn, kMinAlbedoDraws);
  EXPECT_EQ(r.verdict(), Verdict::Inconclusive) << failed(r);
  EXPECT_NE(r.inconclusiveReason().find("reflection lobe was drawn"), std::string::npos)
      << r.inconclusiveReason();
  EXPECT_TRUE(r.delta.lobes[int(DeltaLobe::Reflection)].sharePassed) << failed(r);
  EXPECT_TRUE(r.delta.lobes[int(DeltaLobe::Refraction)].albedoPassed) << failed(r);
}

TEST(DeltaLobes, BadOptionsAreNamed) {
  BsdfCheckOptions o = options("bad eta");
  o.delta.eta = -1;
  EXPECT_THROW(
      {
        try {
          checkBsdf(glassModel({1.5}), incidence(45), o);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("DeltaCheckOptions::eta"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
}

}  // namespace verity::chi2::delta_check_test
