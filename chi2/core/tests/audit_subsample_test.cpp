// The per-sample comparisons on a subsample (CheckOptions::auditedSamples): on a Lambertian
// lobe whose every weight is 1% high they run on the first whole streams only, so the defect
// is counted there and nowhere else, and the report states the subsample and what it could
// have met, 1 − (1 − power)^(1/n) of the samples; the histogram and both statistics are those
// of the check that compares every sample, bit for bit; a defect touching 10⁻³ of the samples,
// far above that reach, is met.
//
// No statistical verdict is asserted: the tests compare counts and statistics between runs, or
// count defects, whose number is certain given the seed (the rare defect is missed by 65,536
// samples with probability (1 − 10⁻³)^65536 ≈ e⁻⁶⁵).
#include <gtest/gtest.h>
#include <verity/chi2/bsdf_adapter.h>
#include <verity/chi2/significance.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "lambert_toy.h"

namespace verity::chi2::audit_subsample_test {

namespace {

using lambert_toy::Vec3;

constexpr double kAlbedo = 0.6;
constexpr long long kStreams = 4;

// A cosine-sampled Lambertian lobe whose weight is 1% high where u.xy.x < `below` (every
// sample for 1, none for 0).
BsdfModel lambert(double below) {
  auto eval = [](const Vec3& wi, const Vec3& wo) {
    return wi.z > 0 && wo.z > 0 ? kAlbedo / std::numbers::pi : 0.0;
  };
  return bsdfModel<Vec3>(
      [=](const Vec3& wi, const BsdfUniforms& u) -> std::optional<SampledDirection<Vec3, double>> {
        if (wi.z <= 0) return std::nullopt;
        const Vec3 wo = lambert_toy::cosineHemisphere(u.xy.x, u.xy.y);
        return SampledDirection<Vec3, double>{wo, kAlbedo * (u.xy.x < below ? 1.01 : 1.0),
                                              lambert_toy::cosinePdf(wo)};
      },
      eval, [](const Vec3&, const Vec3& wo) { return lambert_toy::cosinePdf(wo); });
}

CheckResult check(double below, std::optional<long long> audited) {
  BsdfCheckOptions o;
  o.name = "audit subsample lambert";  // one seed for every run
  o.significance = sidakLevel(0.01, kStatisticalTestsPerCheck);
  o.samples = kStreams * kSamplesPerStream;
  o.auditedSamples = audited;
  return checkBsdf(lambert(below), Vec3{0.5, 0, std::sqrt(0.75)}, o);
}

}  // namespace

TEST(AuditSubsample, ComparesTheFirstWholeStreamsAndStatesWhatTheyCouldMeet) {
  // 10⁵ samples asked for: two whole streams.
  const CheckResult sub = check(1, 100'000);
  const long long streams = 2 * kSamplesPerStream;
  EXPECT_EQ(sub.test.auditedSamples, streams);
  EXPECT_EQ(sub.test.audit.count(Defect::Weight), streams) << sub.report();
  EXPECT_FALSE(sub.test.auditedAll());
  const double reach = 1 - std::pow(1 - kDefaultPower, 1.0 / streams);
  EXPECT_NEAR(sub.test.auditReach, reach, 1e-12 * reach);
  EXPECT_NE(sub.report().find("compared per sample: the first 131072 of the 262144 samples, "
                              "where a defect touching 1.8e-05 of the samples or more would "
                              "have been met with 90% probability"),
            std::string::npos)
      << sub.report();

  const CheckResult all = check(1, std::nullopt);
  EXPECT_EQ(all.test.auditedSamples, kStreams * kSamplesPerStream);
  EXPECT_EQ(all.test.audit.count(Defect::Weight), kStreams * kSamplesPerStream);
  EXPECT_TRUE(all.test.auditedAll());
  EXPECT_EQ(all.report().find("compared per sample"), std::string::npos) << all.report();
}

TEST(AuditSubsample, TheHistogramAndStatisticsAreThoseOfTheFullAudit) {
  const CheckResult sub = check(0, kSamplesPerStream), all = check(0, std::nullopt);
  EXPECT_EQ(sub.test.observed, all.test.observed);
  EXPECT_EQ(sub.test.valid, all.test.valid);
  EXPECT_EQ(sub.test.chiSquare.statistic, all.test.chiSquare.statistic);
  EXPECT_EQ(sub.test.chiSquare.pValue, all.test.chiSquare.pValue);
  EXPECT_EQ(sub.test.integral.passed, all.test.integral.passed);
  EXPECT_EQ(sub.verdict(), all.verdict());
  EXPECT_TRUE(sub.test.audit.clean());
}

TEST(AuditSubsample, ADefectAboveTheReachIsMet) {
  const CheckResult r = check(1e-3, kSamplesPerStream);
  ASSERT_GT(1e-3, r.test.auditReach);
  EXPECT_GT(r.test.audit.count(Defect::Weight), 0) << r.report();
  EXPECT_LE(r.test.audit.count(Defect::Weight), kSamplesPerStream);
  EXPECT_EQ(r.verdict(), Verdict::Failed);
}

TEST(AuditSubsample, ASubsampleOfNoSampleIsRefusedByName) {
  try {
    check(0, 0);
    ADD_FAILURE() << "auditedSamples = 0 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("the samples to audit"), std::string::npos) << e.what();
  }
}

}  // namespace verity::chi2::audit_subsample_test
