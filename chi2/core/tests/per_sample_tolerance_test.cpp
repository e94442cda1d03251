// The per-sample tolerances a caller sets (BsdfCheckOptions::weightTolerance and
// reciprocityTolerance) and the worst |ratio − 1| the report gives beside each defect's first
// example: a Lambertian lobe whose weight, sample pdf or eval carries a relative error of a
// few 10⁻⁴ (float rounding) fails at the defaults with that worst, passes with a tolerance
// set to 10⁻³ or 10⁻², and reads apart from a bug (a worst of 0.5). A narrow lobe whose pdf()
// takes sin²θ as 1 − cos²θ in single precision fails within what rounding the direction gives
// there, and one whose pdf() is 2% off fails beyond it. A ring whose pdf() reads cos θo
// rounded off its peak fails within rounding too, its sample's density up to 7.4 times pdf():
// rounding that only lowers a reference explains a ratio above 1 as well as below.
//
// Level: kCorrectChecks checks of two statistical tests each must pass, at a family-wise level
// of 1% with Šidák's correction; those that must fail use the same level.
#include <gtest/gtest.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/significance.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "lambert_toy.h"

namespace verity::chi2::per_sample_tolerance_test {

namespace {

using lambert_toy::Vec3;

// The weight, the sample pdf and the eval errors, each with its tolerance raised.
constexpr int kCorrectChecks = 3;
const double kLevel = sidakLevel(0.01, kStatisticalTestsPerCheck* kCorrectChecks);
constexpr long long kSamples = 100'000;
constexpr double kAlbedo = 0.6;

enum class Error {
  Weight,       // weight × (1 + size·(2·u.lobe − 1)): |ratio − 1| up to size
  HalfWeights,  // weight × (1 + size) for u.lobe < 1/2: a bug, |ratio − 1| = size
  SamplePdf,    // sample pdf × (1 + size·(2·u.lobe − 1))
  Eval,         // eval × (1 + size·wo.x), the weight kept consistent: not reciprocal
};

// A cosine-sampled Lambertian lobe in Verity's convention, with one error of relative `size`.
BsdfModel lambert(Error error, double size) {
  auto eval = [error, size](const Vec3& wi, const Vec3& wo) {
    if (wi.z <= 0 || wo.z <= 0) return 0.0;
    return kAlbedo / std::numbers::pi * (error == Error::Eval ? 1 + size * wo.x : 1);
  };
  return bsdfModel<Vec3>(
      [=](const Vec3& wi, const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, double>> {
        if (wi.z <= 0) return std::nullopt;
        const Vec3 wo = lambert_toy::cosineHemisphere(u.xy.x, u.xy.y);
        const double jitter = 1 + size * (2 * u.lobe - 1), pdf = lambert_toy::cosinePdf(wo);
        double weight = eval(wi, wo) * wo.z / pdf;
        if (error == Error::Weight) weight *= jitter;
        if (error == Error::HalfWeights && u.lobe < 0.5) weight *= 1 + size;
        return SampledDirection<Vec3, double>{wo, weight,
                                              error == Error::SamplePdf ? pdf * jitter : pdf};
      },
      eval, [](const Vec3&, const Vec3& wo) { return lambert_toy::cosinePdf(wo); });
}

CheckResult check(Error error, double size, const std::string& name,
                  const BsdfCheckOptions& tolerances = {}) {
  BsdfCheckOptions o = tolerances;
  o.name = "tolerance lambert " + name;
  o.significance = kLevel;
  o.samples = kSamples;
  const double t = 40 * std::numbers::pi / 180;
  return checkBsdf(lambert(error, size), Vec3{std::sin(t), 0, std::cos(t)}, o);
}

// The options of a check of a lobe that is not reciprocal by construction (its eval ignores wi,
// or reads a function of wi alone), so that reciprocity is not checked.
BsdfCheckOptions withoutReciprocity(const std::string& name) {
  BsdfCheckOptions o;
  o.name = "tolerance " + name;
  o.significance = kLevel;
  o.samples = kSamples;
  o.checkReciprocity = false;
  return o;
}

BsdfCheckOptions weightTolerance(double t) {
  BsdfCheckOptions o;
  o.weightTolerance = t;
  return o;
}

std::string failed(const CheckResult& r) {
  std::string s;
  for (const std::string& f : r.failures()) s += "[" + f + "] ";
  return s + "\n" + r.report();
}

// A narrow lobe about the normal: the unit disk's density exp(−r²/a²)/(π a²) (a ≪ 1, so its
// tail beyond r = 1 is nil), lifted to the hemisphere, pdf = that·cos θo with r² = sin²θo.
// sample() returns the exact pdf of its direction; pdf() computes sin²θo as 1 − cos²θo in
// float (a cancellation whose condition near the normal is 1/sin²θo: at a = 10⁻³ rounding cos θo
// alone moves r²/a² by some 0.1) or, as a bug, in double with a normalisation 2% high.
enum class LobePdf { FloatCancellation, TwoPercentHigh };

BsdfModel narrowLobe(LobePdf kind, double a) {
  const auto disk = [a](double r2) { return std::exp(-r2 / (a * a)) / (std::numbers::pi * a * a); };
  auto pdf = [=](const Vec3&, const Vec3& wo) {
    if (wo.z <= 0) return 0.0;
    if (kind == LobePdf::TwoPercentHigh) return 1.02 * disk(wo.x * wo.x + wo.y * wo.y) * wo.z;
    const float z = static_cast<float>(wo.z);
    return disk(1.0f - z * z) * wo.z;
  };
  return bsdfModel<Vec3>(
      [=](const Vec3& wi, const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, double>> {
        if (wi.z <= 0) return std::nullopt;
        const double r = a * std::sqrt(-std::log(1 - u.xy.x)), phi = 2 * std::numbers::pi * u.xy.y;
        if (r >= 1) return std::nullopt;
        const Vec3 wo{r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - r * r)};
        return SampledDirection<Vec3, double>{wo, kAlbedo, disk(r * r) * wo.z};
      },
      [=](const Vec3&, const Vec3& wo) {
        return wo.z > 0 ? kAlbedo * disk(wo.x * wo.x + wo.y * wo.y) : 0.0;
      },
      pdf);
}

// A ring of directions about cos θo = z*, halfway between the floats 0.75 and 0.75 + 2⁻²⁴,
// Gaussian in cos θo with σ a quarter of that spacing and uniform in φ (the sphere's area
// element is d(cos θ) dφ): p = g(cos θo) / 2π. sample() returns the exact density of its
// direction; pdf() reads cos θo in float, on the grid 2σ from the peak, so that it is up to
// e² = 7.4 times lower than the sample's, and every move of wo by its rounding (16σ or more)
// lowers it further. The weight agrees with eval·|cos|/pdf(), so only the sample pdf fails.
BsdfModel ringOffTheFloatGrid() {
  const double spacing = std::ldexp(1.0, -24), zPeak = 0.75 + spacing / 2, sigma = spacing / 4;
  const auto g = [=](double z) {
    const double t = (z - zPeak) / sigma;
    return std::exp(-0.5 * t * t) / (sigma * std::sqrt(2 * std::numbers::pi));
  };
  const auto pdfFloat = [=](const Vec3&, const Vec3& wo) {
    return g(static_cast<float>(wo.z)) / (2 * std::numbers::pi);
  };
  return bsdfModel<Vec3>(
      [=](const Vec3& wi, const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, double>> {
        if (wi.z <= 0) return std::nullopt;
        // Box–Muller for cos θo, u.lobe for φ.
        const double n =
            std::sqrt(-2 * std::log(1 - u.xy.x)) * std::cos(2 * std::numbers::pi * u.xy.y);
        const double z = zPeak + sigma * n, r = std::sqrt(1 - z * z);
        const double phi = 2 * std::numbers::pi * u.lobe;
        const Vec3 wo{r * std::cos(phi), r * std::sin(phi), z};
        return SampledDirection<Vec3, double>{wo, kAlbedo, g(z) / (2 * std::numbers::pi)};
      },
      [=](const Vec3& wi, const Vec3& wo) {
        return wo.z > 0 ? kAlbedo * pdfFloat(wi, wo) / wo.z : 0.0;
      },
      pdfFloat);
}

// A cosine-sampled lobe whose albedo is a function of wi alone, steep in float: it climbs 40%
// per float step of wi.x above wi.x's own float x0 (a Fresnel factor at its critical angle in
// miniature), up to four steps. sample() reads it one float step above x0 (another formula,
// rounding otherwise), eval() at x0: a weight 1.4 times eval·|cos|/pdf at every sample, which
// no move of wo changes. As a bug, the same weight with an albedo that does not climb.
enum class AlbedoOfWi { SteepInFloat, SmoothWithAWrongWeight };

BsdfModel albedoOfWi(AlbedoOfWi kind, double x0) {
  const float base = static_cast<float>(x0);
  const auto albedo = [=](float x) {
    if (kind == AlbedoOfWi::SmoothWithAWrongWeight) return kAlbedo;
    int steps = 0;
    for (float f = base; steps < 4 && std::nextafter(f, 2.0f) <= x; ++steps)
      f = std::nextafter(f, 2.0f);
    return kAlbedo * (1 + 0.4 * steps);
  };
  auto eval = [=](const Vec3& wi, const Vec3& wo) {
    return wi.z > 0 && wo.z > 0 ? albedo(static_cast<float>(wi.x)) / std::numbers::pi : 0.0;
  };
  return bsdfModel<Vec3>(
      [=](const Vec3& wi, const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, double>> {
        if (wi.z <= 0) return std::nullopt;
        const Vec3 wo = lambert_toy::cosineHemisphere(u.xy.x, u.xy.y);
        const double weight = kind == AlbedoOfWi::SteepInFloat
                                  ? albedo(std::nextafter(static_cast<float>(wi.x), 2.0f))
                                  : 1.4 * kAlbedo;
        return SampledDirection<Vec3, double>{wo, weight, lambert_toy::cosinePdf(wo)};
      },
      eval, [](const Vec3&, const Vec3& wo) { return lambert_toy::cosinePdf(wo); });
}

}  // namespace

TEST(PerSampleTolerance, DefaultsAreThoseOfTheSuite) {
  const BsdfCheckOptions o;
  EXPECT_EQ(o.weightTolerance, 1e-4);
  EXPECT_EQ(o.reciprocityTolerance, 1e-3);
}

TEST(PerSampleTolerance, InvalidTolerancesAreRejectedNamingTheOption) {
  const BsdfModel m = lambert(Error::Weight, 0);
  for (const char* option : {"weightTolerance", "reciprocityTolerance"}) {
    for (double bad : {-1e-4, 1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
      BsdfCheckOptions o;
      o.name = "tolerance invalid";
      o.significance = kLevel;
      (std::string(option) == "weightTolerance" ? o.weightTolerance : o.reciprocityTolerance) = bad;
      try {
        checkBsdf(m, Vec3{0, 0, 1}, o);
        ADD_FAILURE() << option << " = " << bad << " was accepted";
      } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
      }
    }
  }
}

TEST(PerSampleTolerance, FloatRoundingInTheWeightReadsApartFromABug) {
  const CheckResult rounding = check(Error::Weight, 3e-4, "weight 3e-4");
  EXPECT_EQ(rounding.failures(), std::vector<std::string>{"weight != eval*cos/pdf"})
      << failed(rounding);
  const double worst = rounding.test.audit.worst(Defect::Weight);
  std::cout << rounding.report() << "\n";
  EXPECT_GT(worst, 2.9e-4) << failed(rounding);
  EXPECT_LE(worst, 3e-4 * (1 + 1e-9)) << failed(rounding);
  EXPECT_NE(rounding.report().find("worst |ratio - 1| = 0.0003"), std::string::npos)
      << failed(rounding);

  const CheckResult tolerated =
      check(Error::Weight, 3e-4, "weight 3e-4 at 1e-3", weightTolerance(1e-3));
  EXPECT_TRUE(tolerated.passed()) << failed(tolerated);

  const CheckResult bug = check(Error::HalfWeights, 0.5, "weight bug", weightTolerance(1e-3));
  EXPECT_NEAR(bug.test.audit.worst(Defect::Weight), 0.5, 1e-9) << failed(bug);
  EXPECT_NE(bug.report().find("worst |ratio - 1| = 0.5:"), std::string::npos) << failed(bug);
}

TEST(PerSampleTolerance, FloatRoundingInTheSamplePdfIsTolerated) {
  const CheckResult rounding = check(Error::SamplePdf, 3e-4, "sample pdf 3e-4");
  EXPECT_TRUE(rounding.failed("sample pdf != pdf()")) << failed(rounding);
  EXPECT_GT(rounding.test.audit.worst(Defect::SamplePdf), 2.9e-4) << failed(rounding);
  EXPECT_LE(rounding.test.audit.worst(Defect::SamplePdf), 3e-4 * (1 + 1e-9)) << failed(rounding);
  const CheckResult tolerated =
      check(Error::SamplePdf, 3e-4, "sample pdf 3e-4 at 1e-3", weightTolerance(1e-3));
  EXPECT_TRUE(tolerated.passed()) << failed(tolerated);
}

// eval(wi, wo)/eval(wo, wi) = (1 + δ·wo.x)/(1 + δ·wi.x), |· − 1| up to about 1.64·δ at 40°.
TEST(PerSampleTolerance, FloatRoundingInReciprocityIsTolerated) {
  const CheckResult rounding = check(Error::Eval, 2e-3, "eval 2e-3");
  EXPECT_EQ(rounding.failures(), std::vector<std::string>{"reciprocity"}) << failed(rounding);
  EXPECT_GT(rounding.test.audit.worst(Defect::Reciprocity), 3e-3) << failed(rounding);
  EXPECT_LT(rounding.test.audit.worst(Defect::Reciprocity), 3.3e-3) << failed(rounding);
  BsdfCheckOptions o;
  o.reciprocityTolerance = 1e-2;
  const CheckResult tolerated = check(Error::Eval, 2e-3, "eval 2e-3 at 1e-2", o);
  EXPECT_TRUE(tolerated.passed()) << failed(tolerated);
}

// Merged chunk by chunk, the audit keeps the first example and the largest deviation.
TEST(PerSampleTolerance, TheAuditKeepsTheWorstDeviationAcrossMerges) {
  Audit a, b, c;
  a.record(Defect::Weight, 0.1, 0.2, "first");  // within rounding
  b.record(Defect::Weight, 0.5, 0.1, "worst");
  c.record(Defect::Weight, 0.2, NAN, "later");  // not classified
  a.merge(b);
  a.merge(c);
  EXPECT_EQ(a.count(Defect::Weight), 3);
  EXPECT_EQ(a.worst(Defect::Weight), 0.5);
  EXPECT_EQ(a.worstExample(Defect::Weight), "worst");
  EXPECT_EQ(a.classified(Defect::Weight), 2);
  EXPECT_EQ(a.beyondRounding(Defect::Weight), 1);
  EXPECT_EQ(a.worstBeyondRounding(Defect::Weight), 0.5);
  EXPECT_FALSE(a.onlyRounding());
  Audit within;
  within.record(Defect::SamplePdf, 0.3, 0.4, "rounding");
  EXPECT_TRUE(within.onlyRounding());
  within.record(Defect::NotUnit, "not a comparison");
  EXPECT_FALSE(within.onlyRounding());
  EXPECT_NE(a.describe().find("first: first"), std::string::npos) << a.describe();
  EXPECT_NE(a.describe().find("worst |ratio - 1| = 0.5: worst"), std::string::npos) << a.describe();
  EXPECT_EQ(ratioDeviation(0, 0), 0);
  EXPECT_EQ(ratioDeviation(1, 0), std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(factorDeviation(1, 7.8), 6.8);
  EXPECT_DOUBLE_EQ(factorDeviation(7.8, 1), 6.8);
  EXPECT_EQ(factorDeviation(0, 1), std::numeric_limits<double>::infinity());
  // A factor of 7.8 either way reaches a ratio of 7.8 (|r − 1| = 6.8) and one of 1/7.8.
  EXPECT_DOUBLE_EQ(deviationWithinFactor(7.8, 6.8), 6.8);
  EXPECT_DOUBLE_EQ(deviationWithinFactor(1 / 7.8, 6.8), 1 - 1 / 7.8);
}

// The same failed comparison, told apart by its cause: the float cancellation is within what
// rounding the sampled direction (4 units in the last place of a float) gives its pdf() there;
// the 2% error of a wider lobe is beyond it, at every sample classified (the first
// kClassifiedPerAudit of each chunk's audit and every new worst).
TEST(PerSampleTolerance, RoundingThroughAnIllConditionedFormulaReadsApartFromABug) {
  const BsdfCheckOptions o = withoutReciprocity("narrow lobe");
  const CheckResult rounding =
      checkBsdf(narrowLobe(LobePdf::FloatCancellation, 1e-3), Vec3{0, 0, 1}, o);
  const Audit& r = rounding.test.audit;
  EXPECT_GT(r.count(Defect::SamplePdf), kSamples / 10) << failed(rounding);
  EXPECT_GT(r.worst(Defect::SamplePdf), 0.01) << failed(rounding);
  EXPECT_GE(r.classified(Defect::SamplePdf), kClassifiedPerAudit) << failed(rounding);
  EXPECT_EQ(r.beyondRounding(Defect::SamplePdf), 0) << failed(rounding);
  EXPECT_EQ(r.beyondRounding(Defect::Weight), 0) << failed(rounding);
  EXPECT_NE(rounding.report().find("within what rounding the directions give there"),
            std::string::npos)
      << failed(rounding);

  // At a = 0.05, where rounding cos θo moves the density by some 10⁻⁴: at a = 10⁻³ it moves it
  // by tens of percent, so that a 2% error there is within what a float BSDF can tell.
  const CheckResult bug = checkBsdf(narrowLobe(LobePdf::TwoPercentHigh, 0.05), Vec3{0, 0, 1}, o);
  const Audit& b = bug.test.audit;
  EXPECT_GT(b.count(Defect::SamplePdf), 0) << failed(bug);
  EXPECT_GE(b.classified(Defect::SamplePdf), kClassifiedPerAudit) << failed(bug);
  EXPECT_EQ(b.beyondRounding(Defect::SamplePdf), b.classified(Defect::SamplePdf)) << failed(bug);
  EXPECT_NEAR(b.worstBeyondRounding(Defect::SamplePdf), 0.02 / 1.02, 1e-6) << failed(bug);
  EXPECT_FALSE(b.onlyRounding());
}

// A quantity of wi alone rounds as much as one of wo: a weight 1.4 times eval·|cos|/pdf where
// the albedo climbs 40% per float step of wi.x is within what rounding wi gives there (moving
// wo alone does not change it: Mitsuba 3's and pbrt-v4's conductors of k = 0 at the critical
// angle, reports/peers/mitsuba3-bsdfs.md, finding 2); the same weight against an albedo that
// does not climb is beyond it.
TEST(PerSampleTolerance, RoundingOfTheIncidentDirectionReadsApartFromABug) {
  const BsdfCheckOptions o = withoutReciprocity("albedo of wi");
  const double t = 40 * std::numbers::pi / 180;
  const Vec3 wi{std::sin(t), 0, std::cos(t)};
  const CheckResult rounding = checkBsdf(albedoOfWi(AlbedoOfWi::SteepInFloat, wi.x), wi, o);
  const Audit& r = rounding.test.audit;
  EXPECT_EQ(r.count(Defect::Weight), kSamples) << failed(rounding);
  EXPECT_NEAR(r.worst(Defect::Weight), 0.4, 1e-9) << failed(rounding);
  EXPECT_GE(r.classified(Defect::Weight), kClassifiedPerAudit) << failed(rounding);
  EXPECT_EQ(r.beyondRounding(Defect::Weight), 0) << failed(rounding);

  const CheckResult bug = checkBsdf(albedoOfWi(AlbedoOfWi::SmoothWithAWrongWeight, wi.x), wi, o);
  const Audit& b = bug.test.audit;
  EXPECT_EQ(b.count(Defect::Weight), kSamples) << failed(bug);
  EXPECT_GE(b.classified(Defect::Weight), kClassifiedPerAudit) << failed(bug);
  EXPECT_EQ(b.beyondRounding(Defect::Weight), b.classified(Defect::Weight)) << failed(bug);
}

// Rounding that lowers a reference explains a ratio above 1 as well as one below: pdf() read at
// cos θo rounded off a narrow ring's peak is up to 7.4 times below the sample's exact density,
// and every move of wo by its rounding lowers it further. Measured as |ratio − 1| those moves
// reached no more than 1 (a reference lowered to nothing), so every ratio above 2 was called
// beyond rounding (Mitsuba 3's GGX at exactly 90°, whose half vector rests on the last bit of
// wo.x, read so: reports/peers/mitsuba3-bsdfs.md, finding 4).
TEST(PerSampleTolerance, RoundingThatLowersTheReferenceExplainsARatioAboveOne) {
  const BsdfCheckOptions o = withoutReciprocity("ring off the float grid");
  const CheckResult r = checkBsdf(ringOffTheFloatGrid(), Vec3{0, 0, 1}, o);
  const Audit& a = r.test.audit;
  EXPECT_GT(a.count(Defect::SamplePdf), kSamples / 10) << failed(r);
  EXPECT_GT(a.worst(Defect::SamplePdf), 5) << failed(r);
  EXPECT_EQ(a.count(Defect::Weight), 0) << failed(r);
  EXPECT_GE(a.classified(Defect::SamplePdf), kClassifiedPerAudit) << failed(r);
  EXPECT_EQ(a.beyondRounding(Defect::SamplePdf), 0) << failed(r);
  EXPECT_TRUE(a.onlyRounding()) << failed(r);
}

}  // namespace verity::chi2::per_sample_tolerance_test
