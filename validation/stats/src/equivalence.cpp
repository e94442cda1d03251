#include <verity/stats/equivalence.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace verity::validation {

namespace {

MeanEstimate scaled(const MeanEstimate& e, double x) {
  return {x * e.mean, x * x * e.variance, x * x * x * x * e.dfDenominator};
}

// p of H0: μ_B ≥ x μ_A against μ_B < x μ_A (below = true), or of H0: μ_B ≤ x μ_A against
// μ_B > x μ_A (below = false).
double oneSidedP(const MeanEstimate& a, const MeanEstimate& b, double x, bool below,
                 bool* deterministic) {
  const MeanEstimate bound = scaled(a, x);
  const WelchResult w = welchTest(bound, b);  // t = (M_B − x M_A) / √V, two-sided p
  *deterministic = w.deterministic;
  if (w.deterministic) return (below ? b.mean <= bound.mean : b.mean >= bound.mean) ? 0.0 : 1.0;
  const bool rightSide = below ? w.t < 0 : w.t > 0;
  return rightSide ? w.p / 2 : 1 - w.p / 2;
}

}  // namespace

EquivalenceResult relativeEquivalenceTest(const MeanEstimate& a, const MeanEstimate& b,
                                          double margin) {
  if (!(margin >= 0 && margin < 1))
    throw std::invalid_argument("relativeEquivalenceTest: margin not in [0, 1)");
  EquivalenceResult r;
  r.pLower = oneSidedP(a, b, 1 - margin, false, &r.deterministic);
  r.pUpper = oneSidedP(a, b, 1 + margin, true, &r.deterministic);
  r.p = std::max(r.pLower, r.pUpper);
  return r;
}

double claimableMargin(const MeanEstimate& a, const MeanEstimate& b, double level) {
  if (!(level > 0 && level < 0.5))
    throw std::invalid_argument("claimableMargin: level not in (0, 0.5)");
  const auto passes = [&](double margin) {
    return relativeEquivalenceTest(a, b, margin).p <= level;
  };
  constexpr double kLargest = 1 - 1e-9;
  if (passes(0)) return 0;
  if (!passes(kLargest)) return std::numeric_limits<double>::infinity();
  double low = 0, high = kLargest;
  while (high - low > 1e-6) {
    const double middle = 0.5 * (low + high);
    (passes(middle) ? high : low) = middle;
  }
  return high;
}

}  // namespace verity::validation
