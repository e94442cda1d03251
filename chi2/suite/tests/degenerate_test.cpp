// Materials whose every sample is a delta lobe or none at all: the histogram sees nothing.
// An index-matched rough dielectric (|ior − 1| <= 1e-3, rough_dielectric.h) is a smooth
// pass-through: its delta samples are not tested, so the verdict must be INCONCLUSIVE, naming
// the empty sample, and never PASSED. A diffuse light does not scatter: it declines every
// sample and its pdf claims no mass, which the pdf-integral test checks, and so it is PASSED.
#include <gtest/gtest.h>

#include "chi2/suite/suite.h"

namespace verity::chi2::suite {

namespace {

TestResult runMaterial(const std::string& name, const std::string& json, double incidence) {
  BsdfCase c;
  c.name = name;
  c.json = json;
  c.incidence = incidence;
  return runBsdf(c);
}

void expectNothingTested(const TestResult& r) {
  EXPECT_EQ(r.valid, 0) << r.report();
  EXPECT_EQ(r.verdict(), Verdict::Inconclusive) << r.report();
  EXPECT_NE(r.inconclusiveReason().find("no valid sample"), std::string::npos) << r.report();
  EXPECT_EQ(r.report().find("PASSED"), std::string::npos) << r.report();
}

}  // namespace

TEST(QuickDegenerate, IndexMatchedRoughDielectricIsInconclusive) {
  // 1, and 1 ± 1e-4 from either side: inside the band, where 1.001 (in the suite) is not.
  for (const char* ior : {"1.0", "1.0001", "0.9999000099990001"})
    for (double incidence : {0.0, 60.0})
      expectNothingTested(runMaterial(
          std::string("degenerate_roughdielectric_ior") + ior,
          std::string(R"({"type":"rough_dielectric","alpha":0.3,"ior":)") + ior + "}", incidence));
}

TEST(QuickDegenerate, DiffuseLightPassesOnItsClaimOfNothing) {
  const TestResult r =
      runMaterial("degenerate_diffuse_light", R"({"type":"diffuse_light","emit":1})", 30);
  EXPECT_EQ(r.valid, 0) << r.report();
  EXPECT_EQ(r.deltaSamples, 0) << r.report();
  EXPECT_EQ(r.integral.integral, 0) << r.report();
  EXPECT_EQ(r.verdict(), Verdict::Passed) << r.report();
}

}  // namespace verity::chi2::suite
