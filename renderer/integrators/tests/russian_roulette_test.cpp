// The one Russian roulette rule every path-walking integrator uses: where it starts, that a
// depth beyond every bounce is no roulette at all, and its survival probabilities.
#include "integrators/russian_roulette.h"

#include <gtest/gtest.h>

#include <limits>

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
    EXPECT_TRUE(roulette.survives(bounce, Color3::Constant(1e-3f), sampler, &survival));
    EXPECT_EQ(survival, 1.0f);
  }
  EXPECT_EQ(sampler.draws, 0);
  // After the third scattering event the roulette decides, with one draw.
  EXPECT_FALSE(roulette.survives(2, Color3::Constant(1e-3f), sampler, &survival));
  EXPECT_EQ(sampler.draws, 1);
}

// A depth beyond every bounce is no roulette: no path ends, no weight changes and no sample is
// drawn, so the sample stream is the one of a walk without roulette.
TEST(RussianRoulette, VeryLargeDepthIsNoRoulette) {
  const RussianRoulette roulette(std::numeric_limits<int>::max());
  FixedSampler sampler(0.999f);
  float survival = 0;
  for (int bounce = 0; bounce < 100000; ++bounce) {
    ASSERT_TRUE(roulette.survives(bounce, Color3::Constant(1e-6f), sampler, &survival));
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
    EXPECT_TRUE(roulette.survives(0, c.throughput, below, &survival));
    EXPECT_EQ(survival, c.survival);
    if (c.survival < 1) EXPECT_FALSE(roulette.survives(0, c.throughput, above, &survival));
  }
  FixedSampler sampler(0.0f);
  float survival = 0;
  EXPECT_FALSE(roulette.survives(0, Color3::Zero(), sampler, &survival));
  EXPECT_EQ(sampler.draws, 0);
}

}  // namespace
}  // namespace verity
