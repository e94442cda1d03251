#include <fmt/format.h>
#include <verity/chi2/integral_check.h>

#include <boost/math/distributions/binomial.hpp>

namespace verity::chi2 {

IntegralCheck checkIntegral(double integral, long long samples, long long valid,
                            double significance, double tolerance) {
  using boost::math::binomial_distribution;
  IntegralCheck c;
  c.integral = integral;
  c.tolerance = tolerance;
  c.samples = samples;
  c.valid = valid;
  c.confidence = 1 - significance;
  const double n = static_cast<double>(samples), k = static_cast<double>(valid);
  const double half = significance / 2;
  c.lower = valid == 0 ? 0.0 : binomial_distribution<double>::find_lower_bound_on_p(n, k, half);
  c.upper =
      valid == samples ? 1.0 : binomial_distribution<double>::find_upper_bound_on_p(n, k, half);
  c.passed =
      std::isfinite(integral) && c.upper >= integral - tolerance && c.lower <= integral + tolerance;
  return c;
}

std::string IntegralCheck::describe() const {
  return fmt::format(
      "pdf integral: {:.6f}, valid samples {:.4f}% ({} of {}), {:.6g}% Clopper-Pearson "
      "interval [{:.6f}, {:.6f}], tolerance {:.1e}",
      integral, 100.0 * valid / std::max(1LL, samples), valid, samples, 100 * confidence, lower,
      upper, tolerance);
}

}  // namespace verity::chi2
