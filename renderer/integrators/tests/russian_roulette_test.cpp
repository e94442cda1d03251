// The one Russian roulette rule every path-walking integrator uses: where it starts, that a
// depth beyond every bounce is no roulette at all, and its survival probabilities.
#include "integrators/russian_roulette.h"

#include <gtest/gtest.h>

#include <limits>

#include "materials/dielectric.h"
#include "sampling/sampler.h"

namespace verity {
namespace {

// Returns `value` for every draw and counts the draws.
class FixedSampler : public Sampler {
 public:
  explicit FixedSampler(float value) : value_(value) {}
  void startPixelSample(const Point2i&, int) override {}
  float next1D() override {
    ++draws;
    return value_;
  }
  Point2f next2D() override {
    draws += 2;
    return Point2f(value_, value_);
  }
  std::unique_ptr<Sampler> clone() const override { return std::make_unique<FixedSampler>(*this); }
  int draws = 0;

 private:
  float value_;
};

TEST(RussianRoulette, NoDecisionBeforeItsDepth) {
  const RussianRoulette roulette(3);
  FixedSampler sampler(0.999f);
  float survival = 0;
  for (int bounce : {0, 1}) {
    EXPECT_TRUE(roulette.survives(bounce, Color3::Constant(1e-3f), 1, sampler, &survival));
    EXPECT_EQ(survival, 1.0f);
  }
  EXPECT_EQ(sampler.draws, 0);
  // After the third scattering event the roulette decides, with one draw.
  EXPECT_FALSE(roulette.survives(2, Color3::Constant(1e-3f), 1, sampler, &survival));
  EXPECT_EQ(sampler.draws, 1);
}

// A depth beyond every bounce is no roulette: no path ends, no weight changes and no sample is
// drawn, so the sample stream is the one of a walk without roulette.
TEST(RussianRoulette, VeryLargeDepthIsNoRoulette) {
  const RussianRoulette roulette(std::numeric_limits<int>::max());
  FixedSampler sampler(0.999f);
  float survival = 0;
  for (int bounce = 0; bounce < 100000; ++bounce) {
    ASSERT_TRUE(roulette.survives(bounce, Color3::Constant(1e-6f), 1, sampler, &survival));
    ASSERT_EQ(survival, 1.0f);
  }
  EXPECT_EQ(sampler.draws, 0);
}

// The survival probability is the largest throughput component, at most 1 and at least 0.05;
// a draw below it survives. A zero throughput ends without a draw.
TEST(RussianRoulette, SurvivalProbability) {
  const RussianRoulette roulette(1);
  struct Case {
    Color3 throughput;
    float survival;
  };
  for (const Case& c : {Case{Color3(0.3f, 0.6f, 0.1f), 0.6f}, Case{Color3(2.0f, 0.1f, 0.1f), 1.0f},
                        Case{Color3(0.01f, 0.02f, 0.0f), 0.05f}}) {
    float survival = 0;
    FixedSampler below(c.survival * 0.99f), above(c.survival);
    EXPECT_TRUE(roulette.survives(0, c.throughput, 1, below, &survival));
    EXPECT_EQ(survival, c.survival);
    if (c.survival < 1) EXPECT_FALSE(roulette.survives(0, c.throughput, 1, above, &survival));
  }
  FixedSampler sampler(0.0f);
  float survival = 0;
  EXPECT_FALSE(roulette.survives(0, Color3::Zero(), 1, sampler, &survival));
  EXPECT_EQ(sampler.draws, 0);
}

// Roulette reads the throughput with the refractions' η² divided out: a radiance path of
// scattering weights 0.73 · 0.73 that has entered glass of index 1.5 carries 0.73² / 1.5², yet
// survives with probability 0.73², not 0.73² / 1.5² (it would then weigh 2.25 times too much
// on survival: the fireflies of issue 28 on the glass cross-check scene).
TEST(RussianRoulette, RefractionIsNoLoss) {
  const RussianRoulette roulette(1);
  const float eta = 1.5f, albedo2 = 0.73f * 0.73f;
  const auto entering =
      sampleSmoothDielectric(Vector3f::UnitZ(), eta, 0.99f, TransportMode::Radiance);
  ASSERT_TRUE(entering && (entering->lobe & kTransmission));
  const float etaScale = refractionEtaScale(*entering, TransportMode::Radiance);
  EXPECT_FLOAT_EQ(etaScale, eta * eta);
  const Color3 throughput = albedo2 * entering->weight;
  float survival = 0;
  FixedSampler sampler(0.0f);
  EXPECT_TRUE(roulette.survives(0, throughput, etaScale, sampler, &survival));
  EXPECT_FLOAT_EQ(survival, albedo2);
  // Leaving the glass scales radiance by η² and etaScale by 1/η²: they cancel again.
  const auto leaving =
      sampleSmoothDielectric(-Vector3f::UnitZ(), eta, 0.99f, TransportMode::Radiance);
  ASSERT_TRUE(leaving && (leaving->lobe & kTransmission));
  EXPECT_FLOAT_EQ(etaScale * refractionEtaScale(*leaving, TransportMode::Radiance), 1.0f);
  // Importance is not scaled by refraction, nor is a reflection: nothing to divide out.
  const auto importance =
      sampleSmoothDielectric(Vector3f::UnitZ(), eta, 0.99f, TransportMode::Importance);
  ASSERT_TRUE(importance && (importance->lobe & kTransmission));
  EXPECT_EQ(refractionEtaScale(*importance, TransportMode::Importance), 1.0f);
  const auto reflected =
      sampleSmoothDielectric(Vector3f::UnitZ(), eta, 0.0f, TransportMode::Radiance);
  ASSERT_TRUE(reflected && (reflected->lobe & kReflection));
  EXPECT_EQ(refractionEtaScale(*reflected, TransportMode::Radiance), 1.0f);
}

}  // namespace
}  // namespace verity
