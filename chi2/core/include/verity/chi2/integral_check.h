// The pdf-integral check. When invalid samples (sample() returning nothing) are given
// weight zero, the density returned by pdf() must integrate over the domain to exactly the
// probability that sample() succeeds. The number of valid samples is binomial, so the
// check passes when the exact (Clopper–Pearson 1934) two-sided confidence interval of the
// valid fraction at level α meets [∫pdf − tol, ∫pdf + tol], tol being the stated
// quadrature tolerance. It flags an integral that is too low as well as too high.
#pragma once

#include <string>

namespace verity::chi2 {

struct IntegralCheck {
  double integral = 0;   // ∫ pdf over the domain
  double tolerance = 0;  // quadrature tolerance added to the binomial bound
  long long samples = 0, valid = 0;
  double lower = 0, upper = 1;  // Clopper–Pearson interval of valid / samples
  double confidence = 0;        // the interval's level: 1 − α
  bool passed = false;
  std::string describe() const;
};

// The suite's quadrature tolerance on ∫pdf (absolute; the integral is at most one).
inline constexpr double kIntegralTolerance = 1e-4;

IntegralCheck checkIntegral(double integral, long long samples, long long valid,
                            double significance, double tolerance = kIntegralTolerance);

}  // namespace verity::chi2
