// Proof that the suite can fail: deliberately broken samplers must each be rejected, by
// the check that should catch them, as the sweep checks a BSDF (its cells, its target and
// its compared samples) at the suite's own (Šidák-corrected) level; the same
// reference implementation without a flaw must pass (these controls are counted in the
// suite's declared number of tests).
#include <gtest/gtest.h>
#include <verity/chi2/sampling_check.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "chi2/suite/bsdf_subject.h"
#include "chi2/suite/microfacet_checks.h"
#include "chi2/suite/suite.h"
#include "chi2/suite/suite_significance.h"
#include "failure_figure.h"
#include "reference_ggx.h"
#include "scratch_folder.h"

namespace verity::chi2 {

using testing::failureFigure;
using testing::Flaw;
using testing::ReferenceGgx;

namespace {

TestResult run(Flaw flaw, float ior, double incidence, bool inside, const std::string& name) {
  BsdfSetup s;
  s.name = "reference ggx " + name;
  s.material = std::make_shared<ReferenceGgx>(0.3f, ior, flaw);
  s.wi = incidentDirection(incidence, inside);
  s.resolution = suite::kSweepSphereResolution;
  BsdfSubject subject(s);
  // The sweep's own question of a BSDF (suite.cpp's runBsdf).
  TestOptions o = suite::optionsFor("broken_" + name);
  o.auditedSamples = suite::kComparedSamples;
  return runSamplingTest(subject, o);
}

}  // namespace

// The controls: correct conductor and dielectric (4 cases, suite::controlCaseCount()).
TEST(BrokenSamplers, ReferenceImplementationPasses) {
  for (auto [ior, theta, inside, name] : {std::tuple{0.0f, 30.0, false, "conductor_30"},
                                          std::tuple{0.0f, 80.0, false, "conductor_80"},
                                          std::tuple{1.5f, 45.0, false, "dielectric_out_45"},
                                          std::tuple{1.5f, 30.0, true, "dielectric_in_30"}}) {
    const TestResult r = run(Flaw::None, ior, theta, inside, name);
    EXPECT_TRUE(r.passed()) << r.report() << "\n" << (r.passed() ? "" : failureFigure(r, name));
  }
}

TEST(BrokenSamplers, PdfMissingReflectionJacobianIsRejected) {
  const TestResult r = run(Flaw::MissingJacobian, 0, 30, false, "jacobian");
  EXPECT_FALSE(r.chiSquarePassed()) << r.report();
  EXPECT_FALSE(r.integral.passed) << r.report();
}

TEST(BrokenSamplers, G1FromTheWrongDistributionIsRejected) {
  const TestResult r = run(Flaw::WrongG1, 0, 60, false, "wrong_g1");
  EXPECT_FALSE(r.passed()) << r.report();
  EXPECT_FALSE(r.integral.passed) << r.report();
  // And by the weak white furnace test: GGX's D with Beckmann's G1.
  const MicrofacetDistribution ggx(MicrofacetType::GGX, 0.3f),
      beckmann(MicrofacetType::Beckmann, 0.3f);
  const MicrofacetCheck f = checkWeakFurnace(ggx, beckmann, incidentDirection(60, false));
  EXPECT_FALSE(f.passed) << f.describe();
}

TEST(BrokenSamplers, TransmissionMissingEta2IsRejected) {
  // Invisible to the chi-square test (the pdf is right) but not to reciprocity.
  const TestResult r = run(Flaw::MissingEta2, 1.5f, 45, false, "eta2");
  EXPECT_TRUE(r.chiSquarePassed()) << r.report();
  EXPECT_GT(r.audit.count(Defect::Reciprocity), 0) << r.report();
  EXPECT_FALSE(r.passed());
}

TEST(BrokenSamplers, WeightOffByCosineIsRejected) {
  const TestResult r = run(Flaw::WeightMissingCos, 0, 60, false, "weight_cos");
  EXPECT_GT(r.audit.count(Defect::Weight), 0) << r.report();
  EXPECT_FALSE(r.passed());
}

// The suite's failure message names a figure that exists (a PNG) in the failure directory,
// here moved by VERITY_CHI2_FIGURES so that no figure of a passing test lies beside those of
// real failures.
TEST(BrokenSamplers, AFailureNamesItsFigure) {
  const suite::ScratchFolder folder("verity-chi2-failure-figure");
  const std::filesystem::path& dir = folder.path();
  setenv("VERITY_CHI2_FIGURES", dir.c_str(), 1);
  const TestResult r = run(Flaw::MissingJacobian, 0, 30, false, "figure");
  ASSERT_FALSE(r.passed());
  const std::string message = failureFigure(r);
  unsetenv("VERITY_CHI2_FIGURES");
  const std::string tag = "  figure: ";
  ASSERT_EQ(message.rfind(tag, 0), 0u) << message;
  const std::filesystem::path path = message.substr(tag.size(), message.size() - tag.size() - 1);
  EXPECT_EQ(path, dir / "BrokenSamplers.AFailureNamesItsFigure.png");
  std::ifstream png(path, std::ios::binary);
  char magic[8] = {};
  png.read(magic, 8);
  EXPECT_EQ(std::string(magic, 8), "\x89PNG\r\n\x1a\n") << path;
}

TEST(BrokenSamplers, PdfTwoPercentTooHighIsRejected) {
  // The shape is right (the chi-square test conditions on the valid count); the integral
  // check catches the scale.
  const TestResult r = run(Flaw::PdfTooHigh, 0, 30, false, "pdf_high");
  EXPECT_FALSE(r.integral.passed) << r.report();
  EXPECT_FALSE(r.passed());
}

}  // namespace verity::chi2
