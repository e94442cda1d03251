// The sweep: every warp, microfacet sampler and BSDF configuration of suite.cpp. The
// `Quick` instantiations form the quick subset; the others run under the chi2-full label.
#include "chi2/suite/suite.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

#include "failure_figure.h"

namespace verity::chi2::suite {

namespace {

template <class Case>
std::vector<Case> select(const std::vector<Case>& all, bool quick) {
  std::vector<Case> v;
  for (const Case& c : all)
    if (c.quick == quick) v.push_back(c);
  return v;
}

template <class Case>
std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  return info.param.name;
}

// A failing configuration's message names its figure (failure_figure.h). An inconclusive
// one fails the suite too: the suite claims every configuration was tested. What each one
// could have caught is recorded in the test's properties, from which
// scripts/chi2_power_report tabulates the sweep.
void expectPassed(const TestResult& r) {
  const auto record = [](const char* key, double value) {
    ::testing::Test::RecordProperty(key, fmt::format("{:.6g}", value));
  };
  record("samples", static_cast<double>(r.samples));
  record("valid_samples", static_cast<double>(r.valid));
  record("compared_samples", static_cast<double>(r.auditedSamples));
  if (r.chiSquareRan()) {
    record("dof", r.chiSquare.dof);
    record("statistic", r.chiSquare.statistic);
    record("p_value", r.chiSquare.pValue);
    record("density_error_quarter", r.chiSquarePower.densityError(kStatedMass));
    record("density_error_sixteenth", r.chiSquarePower.densityError(kStatedSmallMass));
  }
  record("quadrature_error", r.quadratureError);
  if (const std::optional<double> d = r.integralPower.detectable())
    record("normalisation_error", *d);
  // Where the time went, phase by phase (scripts/chi2_power_report sums them).
  for (int p = 0; p < static_cast<int>(Phase::Count); ++p)
    if (const double s = r.phases[static_cast<Phase>(p)]; s > 0) {
      std::string key = fmt::format("seconds_{}", phaseName(static_cast<Phase>(p)));
      std::replace(key.begin(), key.end(), ' ', '_');
      record(key.c_str(), s);
    }
  if (r.passed()) return;
  const std::string message = r.report() + "\n" + testing::failureFigure(r);
  EXPECT_EQ(r.inconclusiveReason(), "") << message;
  EXPECT_TRUE(r.chiSquarePassed()) << message;
  EXPECT_TRUE(r.integral.passed) << message;
  EXPECT_TRUE(r.audit.clean()) << message;
}

}  // namespace

class WarpTest : public ::testing::TestWithParam<WarpCase> {};
TEST_P(WarpTest, SamplesMatchPdf) {
  expectPassed(runWarp(GetParam()));
}
INSTANTIATE_TEST_SUITE_P(Quick, WarpTest, ::testing::ValuesIn(select(warpCases(), true)),
                         caseName<WarpCase>);

class MicrofacetTest : public ::testing::TestWithParam<MicrofacetCase> {};
TEST_P(MicrofacetTest, SamplesMatchPdf) {
  expectPassed(runMicrofacet(GetParam()));
}
INSTANTIATE_TEST_SUITE_P(Quick, MicrofacetTest,
                         ::testing::ValuesIn(select(microfacetCases(), true)),
                         caseName<MicrofacetCase>);
INSTANTIATE_TEST_SUITE_P(Full, MicrofacetTest,
                         ::testing::ValuesIn(select(microfacetCases(), false)),
                         caseName<MicrofacetCase>);

// The distribution's own checks do not depend on the sampling mode: once per distribution,
// alpha and incidence (the furnace) or per distribution and alpha (the normalisation).
std::vector<MicrofacetCase> distributionCases(bool perIncidence) {
  std::vector<MicrofacetCase> v;
  for (const MicrofacetCase& c : microfacetCases())
    if (c.sampling == MicrofacetSampling::Visible && (perIncidence || c.incidence == 0))
      v.push_back(c);
  return v;
}

class MicrofacetFurnaceTest : public ::testing::TestWithParam<MicrofacetCase> {};
TEST_P(MicrofacetFurnaceTest, WeakWhiteFurnace) {
  const MicrofacetCase& c = GetParam();
  const MicrofacetCheck r = checkWeakFurnace(c.distribution(), c.wi());
  EXPECT_TRUE(r.passed) << r.describe();
}
INSTANTIATE_TEST_SUITE_P(Full, MicrofacetFurnaceTest, ::testing::ValuesIn(distributionCases(true)),
                         caseName<MicrofacetCase>);

class MicrofacetNormalisationTest : public ::testing::TestWithParam<MicrofacetCase> {};
TEST_P(MicrofacetNormalisationTest, Normalisation) {
  const MicrofacetCheck r = checkNormalisation(GetParam().distribution());
  EXPECT_TRUE(r.passed) << r.describe();
}
INSTANTIATE_TEST_SUITE_P(Quick, MicrofacetNormalisationTest,
                         ::testing::ValuesIn(distributionCases(false)), caseName<MicrofacetCase>);

class LightTest : public ::testing::TestWithParam<LightCase> {};
TEST_P(LightTest, SamplesMatchPdf) {
  expectPassed(runLight(GetParam()));
}
INSTANTIATE_TEST_SUITE_P(Quick, LightTest, ::testing::ValuesIn(select(lightCases(), true)),
                         caseName<LightCase>);

class BsdfTest : public ::testing::TestWithParam<BsdfCase> {};
TEST_P(BsdfTest, SamplesMatchPdf) {
  const TestResult r = runBsdf(GetParam());
  if (!GetParam().weaker.empty()) ::testing::Test::RecordProperty("weaker", GetParam().weaker);
  expectPassed(r);
  EXPECT_GE(r.chiSquare.dof, GetParam().minDof) << r.report();
}
INSTANTIATE_TEST_SUITE_P(Quick, BsdfTest, ::testing::ValuesIn(select(bsdfCases(), true)),
                         caseName<BsdfCase>);
INSTANTIATE_TEST_SUITE_P(Full, BsdfTest, ::testing::ValuesIn(select(bsdfCases(), false)),
                         caseName<BsdfCase>);

}  // namespace verity::chi2::suite
