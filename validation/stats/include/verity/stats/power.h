// The power of the per-tile Welch tests with the Holm decision: how large a uniform relative
// brightness bias (image B's expectation times 1 + r) the comparison detects.
//
// Holm rejects anything exactly when some p ≤ α/m, so the probability of the decision
// "differ" is that of any test passing the Bonferroni threshold c = t_{ν, 1−α/(2m)}. Under a
// bias r a test's statistic is approximately δ + T_ν with δ = r·M / √V (M the tile's mean, V
// its estimated variance), and passes with probability P(T_ν > c − δ) + P(T_ν < −c − δ).
// Tests of one channel are independent (disjoint pixels), so within a channel
// P(any) = 1 − Π (1 − P_j); channels of one tile are not independent, and the maximum over
// the channels is a lower bound of the whole decision's power. Deterministic tests (V = 0)
// are left out: any bias there is detected for certain, which says nothing about the noise.
// The variances are the measured ones, so the figure is an estimate, good when V is
// estimated from many samples.
#pragma once

#include <vector>

namespace verity::validation {

struct PowerTerm {
  double mean = 0;      // the tile's mean (average of the two images)
  double variance = 0;  // V_A + V_B
  double df = 0;        // Welch–Satterthwaite degrees of freedom
  int group = 0;        // tests in one group are independent (the colour channel)
};

// Lower bound of the probability that the comparison reports "differ" under a uniform
// relative bias r, with m tests in the Holm family at level alpha.
double rejectionProbability(const std::vector<PowerTerm>& terms, int m, double alpha, double r);

// The smallest r ≥ 0 whose rejectionProbability is at least `power` (bisection to 1e-6
// relative); infinity when none up to r = 100 is.
double detectableRelativeBias(const std::vector<PowerTerm>& terms, int m, double alpha,
                              double power);

}  // namespace verity::validation
