// Welch's two-sample t-test for means whose variances need not be equal, with the
// Welch–Satterthwaite degrees of freedom (B. L. Welch 1947, "The generalization of
// 'Student's' problem when several different population variances are involved",
// Biometrika 34; F. E. Satterthwaite 1946, "An approximate distribution of estimates of
// variance components", Biometrics Bulletin 2). Used per tile by Jung, Hanika and
// Dachsbacher 2020, "Detecting Bias in Monte Carlo Renderers using Welch's t-test", JCGT 9(2).
#pragma once

namespace verity::validation {

// An estimate of a mean whose variance is itself estimated as a sum of independent terms
// V = Σ_i a_i s_i², each s_i² an unbiased sample variance with n_i − 1 degrees of freedom.
// For a plain sample of n values: V = s²/n and dfDenominator = (s²/n)² / (n − 1).
struct MeanEstimate {
  double mean = 0;
  double variance = 0;       // V: the estimated variance of `mean`
  double dfDenominator = 0;  // Σ_i (a_i s_i²)² / (n_i − 1), for the Satterthwaite df
};

struct WelchResult {
  double t = 0;   // (B − A) / sqrt(V_A + V_B); 0 when deterministic
  double df = 0;  // Welch–Satterthwaite degrees of freedom; infinity when deterministic
  double p = 1;   // two-sided p-value
  // Both variances were zero: no randomness to test. p is 1 when the means are exactly
  // equal and 0 when they differ at all.
  bool deterministic = false;
};

// The estimate of a plain sample's mean (n ≥ 2) from its mean and unbiased sample variance.
MeanEstimate sampleMean(double mean, double sampleVariance, double n);

// Tests H0: E[A] = E[B] for independent estimates A and B.
//   t = (B − A) / sqrt(V_A + V_B),
//   ν = (V_A + V_B)² / (dfDenominator_A + dfDenominator_B)   (Satterthwaite 1946; Welch 1947)
//   p = 2 · P(T_ν > |t|)   with T_ν Student's t (boost::math::students_t).
// Throws std::invalid_argument for negative or non-finite inputs.
WelchResult welchTest(const MeanEstimate& a, const MeanEstimate& b);

}  // namespace verity::validation
