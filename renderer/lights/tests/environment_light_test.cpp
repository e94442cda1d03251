#include "lights/environment_light.h"

#include <gtest/gtest.h>

#include "sampling/independent_sampler.h"
#include "sampling/warp.h"

namespace verity {
namespace {

TEST(EnvironmentLight, UvMappingRoundTrips) {
  for (const Vector3f d :
       {Vector3f(0, 1, 0.001f), Vector3f(1, 0, 0), Vector3f(0.3f, -0.5f, -0.8f)}) {
    const Vector3f n = d.normalized();
    EXPECT_TRUE(
        EnvironmentLight::uvToDirection(EnvironmentLight::directionToUv(n)).isApprox(n, 1e-4f));
  }
}

// The importance-sampled image background: E[L / pdf] over the sphere equals ∫ L dω, which
// uniform sampling estimates too; the two estimates must agree within their errors.
TEST(EnvironmentLight, ImportanceSamplingIsUnbiased) {
  auto image = std::make_shared<ImageTexture>(VERITY_SOURCE_DIR "/scenes/textures/earth.png", "bg");
  const EnvironmentLight light(image);
  IndependentSampler sampler;
  sampler.startPixelSample(Point2i(0, 0), 0);
  const int n = 200000;
  double sumIs = 0, sumIs2 = 0, sumU = 0, sumU2 = 0;
  for (int i = 0; i < n; ++i) {
    const auto s = light.sampleLi(Point3f::Zero(), sampler.next2D());
    ASSERT_TRUE(s.has_value());
    ASSERT_EQ(s->pdf, light.pdfLi(s->wi));
    const double vIs = luminance(s->radiance) / s->pdf;
    sumIs += vIs;
    sumIs2 += vIs * vIs;
    const Vector3f d = warp::squareToUniformSphere(sampler.next2D());
    const double vU = luminance(light.radiance(d)) * 4 * kPi;
    sumU += vU;
    sumU2 += vU * vU;
  }
  const double mIs = sumIs / n, mU = sumU / n;
  const double se = std::sqrt((sumIs2 / n - mIs * mIs) / n + (sumU2 / n - mU * mU) / n);
  // Two-sided z-test at significance 0.1% (one test).
  EXPECT_NEAR(mIs, mU, 3.29 * se);
}

}  // namespace
}  // namespace verity
