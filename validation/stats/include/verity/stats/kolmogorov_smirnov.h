// One-sample Kolmogorov–Smirnov test of uniformity on [0, 1], used on the tiles' p-values:
// under the null hypothesis (both images estimate the same expectations) every p-value is
// U(0, 1), and a bias spread thinly over many tiles shows as a surplus of small p-values even
// where no single tile is significant (Jung et al. 2020 inspect the p-value histogram).
//
// Statistic: D = max_i max(i/n − u_(i), u_(i) − (i − 1)/n) over the sorted values.
// p-value: the asymptotic Kolmogorov distribution, P(√n D > λ) → Q(λ) =
// 2 Σ_{k≥1} (−1)^{k−1} exp(−2 k² λ²) (Kolmogorov 1933), evaluated at Stephens' (1970)
// small-sample corrected λ = (√n + 0.12 + 0.11/√n) D, accurate to about 1% in p for n ≥ 5.
//
// Assumptions: the values are independent and identically distributed and, under the
// null, EXACTLY U(0, 1) and continuous (no ties, no atoms). For tile p-values this needs
// independent tiles (true for per-pixel random numbers, false where light-tracing splats
// one path into many pixels) and a correct t-distribution: the tile means close to normal
// and the Satterthwaite approximation good. Heavy-tailed pixel samples (fireflies, caustics)
// make variances underestimated in most tiles and the p-values too small: KS then rejects a
// correct pair. Deterministic tiles (p exactly 0 or 1) must be left out.
#pragma once

#include <vector>

namespace verity::validation {

struct KsResult {
  int n = 0;
  double statistic = 0;  // D
  double pValue = 1;     // 1 when n = 0
};

// Q(λ) = lim P(√n D > λ); 1 for λ ≤ 0.
double kolmogorovSurvival(double lambda);

// Values must lie in [0, 1] (std::invalid_argument otherwise).
KsResult ksTestUniform(std::vector<double> values);

}  // namespace verity::validation
