// The MIS weights of bidirectional path tracing: for any path, the weights of the strategies
// that can sample it sum to one (the condition for an unbiased combination, Veach 1997,
// §9.2), with delta vertices, zero densities and either heuristic.
#include "integrators/bdpt_mis.h"

#include <gtest/gtest.h>

#include <random>

namespace verity {
namespace {

bool usable(const MisPath& p, int t) {
  if (t == p.n) return true;
  if (t == 1 && p.n == 2 && p.endpointAtInfinity) return false;
  return !p.delta[t - 1] && !p.delta[t];
}

TEST(BdptMis, WeightsOfUsableStrategiesSumToOne) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u01(0, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    MisPath p;
    const int n = 2 + trial % 9;
    p.reset(n);
    for (int i = 1; i < n - 1; ++i) p.delta[i] = u01(rng) < 0.25;
    for (int i = 1; i < n; ++i) {
      // Densities spanning many orders of magnitude; deltas stored as 0.
      p.C[i] = p.delta[i - 1] ? 0 : std::exp(20 * (u01(rng) - 0.5));
      p.L[i] = i + 1 < n && p.delta[i + 1] ? 0 : std::exp(20 * (u01(rng) - 0.5));
    }
    p.nextEventPdf = std::exp(10 * (u01(rng) - 0.5));
    p.lightPathPdf = std::exp(10 * (u01(rng) - 0.5));
    p.endpointAtInfinity = trial % 3 == 0;
    for (float power : {1.0f, 2.0f}) {
      double sum = 0;
      for (int t = 1; t <= n; ++t) {
        const float w = bdptMisWeight(p, t, power);
        EXPECT_GE(w, 0);
        EXPECT_LE(w, 1);
        if (usable(p, t)) sum += w;
      }
      EXPECT_NEAR(sum, 1.0, 1e-5) << "trial " << trial << " power " << power;
    }
  }
}

TEST(BdptMis, ZeroDensityStrategiesGetNothingAndLeaveTheRest) {
  // A path of 4 vertices whose next-event density is zero (an emitter NEE cannot choose):
  // strategy t = 3 (s = 1) has weight 0 and the others still sum to one.
  MisPath p;
  p.reset(4);
  p.C = {0, 1, 2, 3};
  p.L = {0, 4, 5, 6};
  p.nextEventPdf = 0;
  p.lightPathPdf = 0.5;
  EXPECT_EQ(bdptMisWeight(p, 3, 1), 0.0f);
  double sum = 0;
  for (int t : {1, 2, 4}) sum += bdptMisWeight(p, t, 1);
  EXPECT_NEAR(sum, 1.0, 1e-6);
  // Balance heuristic by hand for t = 4 (s = 0): p_t = Π C_1..C_{t−1} Π L_t..L_{n−2} E_t.
  const double p1 = 4 * 5 * 0.5, p2 = 1 * 5 * 0.5, p4 = 1 * 2 * 3;
  EXPECT_NEAR(bdptMisWeight(p, 4, 1), p4 / (p1 + p2 + p4), 1e-6);
  EXPECT_NEAR(bdptMisWeight(p, 1, 2), p1 * p1 / (p1 * p1 + p2 * p2 + p4 * p4), 1e-6);
}

}  // namespace
}  // namespace verity
