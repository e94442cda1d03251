// The stochastic mode on toys in their own types: a "layered" Lambertian whose eval and sample
// weight are unbiased random estimates passes, and fails when either estimate is 2% low; its
// four-component twin passes, and fails when its fourth component alone is 2% low; a
// deterministic Phong lobe checked without its pdf passes, and fails with its weight wrong.
//
// Level: the correct subjects are 3 checks of kStatisticalTestsPerStochasticCheck tests, at a
// family-wise level of 1% with Šidák's correction (per test about 0.0025; per component of
// the total albedo about 0.00084, z = 3.34). Power: with 400,000 draws and 128 cells of 32 × 32
// evaluations the layered toy's total albedo has a standard error of about 0.14% of it (the
// evaluations' 0.13% dominating), so a 2% error is some 14 standard errors (the checks find
// t = 16.5 and −14.5): power above 1 − 10⁻²⁰ (normal approximation). The test asserts the
// check's own figure, the smallest error found with 90% power, to be below 1% (it is 0.64%).
// The Phong lobe's weight is 1.9% low, 29 standard errors.
#include <gtest/gtest.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/significance.h>
#include <verity/chi2/stochastic_check.h>

#include "layered_toy.h"
#include "phong_toy.h"

namespace verity::chi2::stochastic_check_test {

namespace {

using layered_toy::Flaw;
using layered_toy::layeredModel;
using layered_toy::Spectrum4;
using phong_toy::Rgb;
using phong_toy::Vec3;

constexpr int kCorrectChecks = 3;
const double kLevel = sidakLevel(0.01, kStatisticalTestsPerStochasticCheck* kCorrectChecks);

StochasticCheckOptions options(const std::string& name) {
  StochasticCheckOptions o;
  o.name = "stochastic " + name;
  o.significance = kLevel;
  o.samples = 400'000;
  return o;
}

const Vec3 kWi{0.5, 0, 0.8660254037844386};

template <class Value = Rgb>
StochasticCheck checkLayered(Flaw flaw, const std::string& name) {
  const StochasticCheckOptions o = options(name);
  return checkStochasticBsdf(layeredModel<Value>(flaw, o.name), kWi, o);
}

}  // namespace

TEST(StochasticBsdf, UnbiasedLayeredToyPasses) {
  const StochasticCheck r = checkLayered(Flaw::None, "layered");
  EXPECT_EQ(r.verdict(), Verdict::Passed) << r.report();
  EXPECT_LT(r.detectableTotal, 0.01) << r.report();
  EXPECT_GT(r.cellTests.size(), 60u * 3) << r.report();
}

TEST(StochasticBsdf, EvalTwoPercentLowIsRejected) {
  const StochasticCheck r = checkLayered(Flaw::EvalLow, "layered eval 2% low");
  EXPECT_EQ(r.verdict(), Verdict::Failed) << r.report();
  EXPECT_TRUE(r.failed("total albedo")) << r.report();
}

TEST(StochasticBsdf, SampledWeightTwoPercentLowIsRejected) {
  const StochasticCheck r = checkLayered(Flaw::WeightLow, "layered weight 2% low");
  EXPECT_EQ(r.verdict(), Verdict::Failed) << r.report();
  EXPECT_TRUE(r.failed("total albedo")) << r.report();
}

// An error of ±10% that leaves the total albedo as it is: the cells find it (each cell's mean
// is found with 90% power from an error of 7.3%, and some 60 cells hold such an error), and
// the total, whose null hypothesis is true, passes at its level.
TEST(StochasticBsdf, LocalErrorIsFoundByTheCells) {
  const StochasticCheck r = checkLayered(Flaw::WeightSkewed, "layered weight skewed");
  EXPECT_EQ(r.verdict(), Verdict::Failed) << r.report();
  EXPECT_TRUE(r.failed("cells")) << r.report();
  EXPECT_FALSE(r.failed("total albedo")) << r.report();
}

// Four components, as pbrt-v4's SampledSpectrum has: the check once summed every value into
// three-component arrays, writing past them, and tested three components at most.
TEST(StochasticBsdf, FourComponentLayeredToyPasses) {
  const StochasticCheck r = checkLayered<Spectrum4>(Flaw::None, "layered spectral");
  EXPECT_EQ(r.verdict(), Verdict::Passed) << r.report();
  EXPECT_EQ(r.components, 4);
  EXPECT_EQ(r.total.size(), 4u) << r.report();
  EXPECT_GT(r.cellTests.size(), 60u * 4) << r.report();
}

// Its fourth component alone 2% low in eval (some 14 standard errors, as above): only that
// component's total albedo can find it.
TEST(StochasticBsdf, FourthComponentTwoPercentLowIsRejected) {
  const StochasticCheck r =
      checkLayered<Spectrum4>(Flaw::FourthEvalLow, "layered spectral fourth eval 2% low");
  EXPECT_EQ(r.verdict(), Verdict::Failed) << r.report();
  EXPECT_TRUE(r.failed("total albedo")) << r.report();
  ASSERT_EQ(r.total.size(), 4u) << r.report();
  EXPECT_LT(r.total[3].p, sidakLevel(kLevel, 4)) << r.report();
}

// A value whose size differs from the model's is a defect, not a read or a write past the
// check's sums.
TEST(StochasticBsdf, AValueOfAnotherSizeIsADefect) {
  StochasticCheckOptions o = options("layered wrong size");
  o.samples = 5000;
  BsdfModel m = layeredModel<Spectrum4>(Flaw::None, o.name);
  m.components = 3;
  const StochasticCheck r = checkStochasticBsdf(m, kWi, o);
  EXPECT_EQ(r.verdict(), Verdict::Failed) << r.report();
  EXPECT_TRUE(r.failed(defectName(Defect::Size))) << r.report();
}

// A deterministic BSDF without a pdf: the Phong lobe, whose sample weight is right or forgets
// the ratio (n+2)/(n+1) (about 2% at n = 50).
TEST(StochasticBsdf, DeterministicBsdfWithoutPdfIsChecked) {
  for (auto flaw : {phong_toy::Flaw::None, phong_toy::Flaw::Weight}) {
    const phong_toy::Phong p(50, flaw);
    const BsdfModel m = bsdfModel<Vec3>(
        [p](const Vec3& wi, const BsdfUniforms& u) { return p.sample(wi, u.xy.x, u.xy.y); },
        [p](const Vec3& wi, const Vec3& wo) { return p.eval(wi, wo); },
        [](const Vec3&, const Vec3&) { return 0.0; });
    const StochasticCheckOptions o =
        options(flaw == phong_toy::Flaw::None ? "phong" : "phong weight");
    const StochasticCheck r = checkStochasticBsdf(m, kWi, o);
    EXPECT_EQ(r.verdict(), flaw == phong_toy::Flaw::None ? Verdict::Passed : Verdict::Failed)
        << r.report();
  }
}

TEST(StochasticBsdf, BadOptionsAreNamed) {
  StochasticCheckOptions o = options("bad strata");
  o.strata = 1;
  EXPECT_THROW(checkStochasticBsdf(layeredModel(Flaw::None, o.name), kWi, o),
               std::invalid_argument);
  o = options("no level");
  o.significance = 0;
  EXPECT_THROW(checkStochasticBsdf(layeredModel(Flaw::None, o.name), kWi, o),
               std::invalid_argument);
}

}  // namespace verity::chi2::stochastic_check_test
