// Equivalence within a relative margin by two one-sided tests (D. J. Schuirmann 1987, "A
// comparison of the two one-sided tests procedure and the power approach for assessing the
// equivalence of average bioavailability", J. Pharmacokinetics and Biopharmaceutics 15(6),
// 657–680), for B's expectation within ±δ of A's, μ_A ≥ 0 (radiance):
//     H0_L: μ_B ≤ (1 − δ) μ_A   against   μ_B > (1 − δ) μ_A,
//     H0_U: μ_B ≥ (1 + δ) μ_A   against   μ_B < (1 + δ) μ_A.
// Each bound is a linear contrast, so each test is a Welch t-test (welch_t.h) of B against A
// scaled by x = 1 ∓ δ: mean x M_A, variance x² V_A, Satterthwaite denominator x⁴ D_A (the
// relative margin without a ratio's Fieller interval). Equivalence is claimed at level β when
// both one-sided p-values are at most β, that is when the (1 − 2β) interval lies within the
// margin. The size is β for one test; for many tests all of which must pass (every tile of an
// image) the intersection-union principle (R. L. Berger 1982, Technometrics 24(4)) keeps it at
// β with no correction.
//
// Deterministic tests (both variances zero) pass exactly when (1 − δ) M_A ≤ M_B ≤ (1 + δ) M_A:
// a black tile on both sides is equivalent.
#pragma once

#include <verity/stats/welch_t.h>

namespace verity::validation {

struct EquivalenceResult {
  double pLower = 1, pUpper = 1;  // one-sided p-values of H0_L and H0_U
  double p = 1;                   // max of the two: equivalence at level β when p ≤ β
  bool deterministic = false;
};

// margin δ in [0, 1) (std::invalid_argument otherwise).
EquivalenceResult relativeEquivalenceTest(const MeanEstimate& a, const MeanEstimate& b,
                                          double margin);

// The smallest margin δ that relativeEquivalenceTest passes at level β in (0, 0.5) (bisection to
// 1e-6); infinity when none below 1 does.
double claimableMargin(const MeanEstimate& a, const MeanEstimate& b, double level);

}  // namespace verity::validation
