// The one Russian roulette rule every path-walking integrator uses: where it starts (counting
// non-specular events only), that a depth beyond every bounce is no roulette at all, and its
// survival probabilities.
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

// A history of `n` non-specular events and no refraction.
RouletteHistory afterEvents(int n) {
  RouletteHistory h;
  h.nonDeltaEvents = n;
  return h;
}

TEST(RussianRoulette, NoDecisionBeforeItsDepth) {
  const RussianRoulette roulette(3, 1.0f);
  FixedSampler sampler(0.999f);
  float survival = 0;
  for (int events : {0, 1, 2}) {
    EXPECT_TRUE(
        roulette.survives(afterEvents(events), Color3::Constant(1e-3f), sampler, &survival));
    EXPECT_EQ(survival, 1.0f);
  }
  EXPECT_EQ(sampler.draws, 0);
  // After the third non-specular scattering event the roulette decides, with one draw.
  EXPECT_FALSE(roulette.survives(afterEvents(3), Color3::Constant(1e-3f), sampler, &survival));
  EXPECT_EQ(sampler.draws, 1);
}

// Specular events (smooth glass and mirrors sample delta lobes) do not bring the roulette's
// start nearer; a non-specular event does, and once started the roulette decides after specular
// events too.
TEST(RussianRoulette, SpecularEventsDoNotCountTowardsItsStart) {
  const RussianRoulette roulette(1, 1.0f);
  const Color3 throughput = Color3::Constant(1e-3f);
  FixedSampler sampler(0.999f);
  float survival = 0;
  RouletteHistory history;
  for (float uLobe : {0.0f, 0.99f, 0.0f, 0.99f}) {  // reflections and refractions
    const auto specular =
        sampleSmoothDielectric(Vector3f(0.3f, 0, 0.9539f), 1.5f, uLobe, TransportMode::Radiance);
    ASSERT_TRUE(specular && specular->isDelta());
    history.record(*specular, TransportMode::Radiance);
    EXPECT_TRUE(roulette.survives(history, throughput, sampler, &survival));
  }
  EXPECT_EQ(history.nonDeltaEvents, 0);
  EXPECT_EQ(sampler.draws, 0);
  BsdfSample diffuse;  // what a Lambertian surface samples
  diffuse.lobe = kReflection | kDiffuse;
  diffuse.weight = Color3::Constant(0.5f);
  ASSERT_FALSE(diffuse.isDelta());
  history.record(diffuse, TransportMode::Radiance);
  EXPECT_EQ(history.nonDeltaEvents, 1);
  EXPECT_FALSE(roulette.survives(history, throughput, sampler, &survival));
  EXPECT_EQ(sampler.draws, 1);
  const auto specular =
      sampleSmoothDielectric(Vector3f::UnitZ(), 1.5f, 0.0f, TransportMode::Radiance);
  history.record(*specular, TransportMode::Radiance);
  EXPECT_FALSE(roulette.survives(history, throughput, sampler, &survival));
  EXPECT_EQ(sampler.draws, 2);
}

// A depth beyond every bounce is no roulette: no path ends, no weight changes and no sample is
// drawn, so the sample stream is the one of a walk without roulette.
TEST(RussianRoulette, VeryLargeDepthIsNoRoulette) {
  const RussianRoulette roulette(std::numeric_limits<int>::max(), 1.0f);
  FixedSampler sampler(0.999f);
  float survival = 0;
  for (int events = 0; events < 100000; ++events) {
    ASSERT_TRUE(
        roulette.survives(afterEvents(events), Color3::Constant(1e-6f), sampler, &survival));
    ASSERT_EQ(survival, 1.0f);
  }
  EXPECT_EQ(sampler.draws, 0);
}

// The survival probability is the largest throughput component over the threshold, at most 1
// and at least 0.05; a draw below it survives, and a path at or above the threshold survives
// whatever it draws. A zero throughput ends without a draw.
TEST(RussianRoulette, SurvivalProbability) {
  struct Case {
    float threshold;
    Color3 throughput;
    float survival;
  };
  for (const Case& c :
       {Case{1, Color3(0.3f, 0.6f, 0.1f), 0.6f}, Case{1, Color3(2.0f, 0.1f, 0.1f), 1.0f},
        Case{1, Color3(0.01f, 0.02f, 0.0f), 0.05f}, Case{0.5f, Color3(0.3f, 0.1f, 0.2f), 0.6f},
        Case{0.5f, Color3(0.1f, 0.5f, 0.1f), 1.0f},
        Case{0.5f, Color3(0.01f, 0.02f, 0.0f), 0.05f}}) {
    const RussianRoulette roulette(1, c.threshold);
    float survival = 0;
    FixedSampler below(c.survival * 0.99f), above(c.survival < 1 ? c.survival : 0.999f);
    EXPECT_TRUE(roulette.survives(afterEvents(1), c.throughput, below, &survival));
    EXPECT_EQ(survival, c.survival) << c.threshold << ": " << c.throughput.transpose();
    EXPECT_EQ(roulette.survives(afterEvents(1), c.throughput, above, &survival), c.survival == 1)
        << c.threshold << ": " << c.throughput.transpose();
  }
  const RussianRoulette roulette(1, 1.0f);
  FixedSampler sampler(0.0f);
  float survival = 0;
  EXPECT_FALSE(roulette.survives(afterEvents(1), Color3::Zero(), sampler, &survival));
  EXPECT_EQ(sampler.draws, 0);
}

// Roulette reads the throughput with the refractions' η² divided out: a radiance path of
// scattering weights 0.73 · 0.73 that has entered glass of index 1.5 carries 0.73² / 1.5², yet
// survives with probability 0.73², not 0.73² / 1.5² (it would then weigh 2.25 times too much
// on survival: fireflies on the glass cross-check scene).
TEST(RussianRoulette, RefractionIsNoLoss) {
  const RussianRoulette roulette(0, 1.0f);
  const float eta = 1.5f, albedo2 = 0.73f * 0.73f;
  const auto entering =
      sampleSmoothDielectric(Vector3f::UnitZ(), eta, 0.99f, TransportMode::Radiance);
  ASSERT_TRUE(entering && (entering->lobe & kTransmission));
  RouletteHistory history;
  history.record(*entering, TransportMode::Radiance);
  EXPECT_FLOAT_EQ(history.etaScale, eta * eta);
  const Color3 throughput = albedo2 * entering->weight;
  float survival = 0;
  FixedSampler sampler(0.0f);
  EXPECT_TRUE(roulette.survives(history, throughput, sampler, &survival));
  EXPECT_FLOAT_EQ(survival, albedo2);
  // Leaving the glass scales radiance by η² and etaScale by 1/η²: they cancel again.
  const auto leaving =
      sampleSmoothDielectric(-Vector3f::UnitZ(), eta, 0.99f, TransportMode::Radiance);
  ASSERT_TRUE(leaving && (leaving->lobe & kTransmission));
  history.record(*leaving, TransportMode::Radiance);
  EXPECT_FLOAT_EQ(history.etaScale, 1.0f);
  // Importance is not scaled by refraction, nor is a reflection: nothing to divide out.
  const auto importance =
      sampleSmoothDielectric(Vector3f::UnitZ(), eta, 0.99f, TransportMode::Importance);
  ASSERT_TRUE(importance && (importance->lobe & kTransmission));
  RouletteHistory light;
  light.record(*importance, TransportMode::Importance);
  EXPECT_EQ(light.etaScale, 1.0f);
  const auto reflected =
      sampleSmoothDielectric(Vector3f::UnitZ(), eta, 0.0f, TransportMode::Radiance);
  ASSERT_TRUE(reflected && (reflected->lobe & kReflection));
  RouletteHistory mirror;
  mirror.record(*reflected, TransportMode::Radiance);
  EXPECT_EQ(mirror.etaScale, 1.0f);
}

}  // namespace
}  // namespace verity
