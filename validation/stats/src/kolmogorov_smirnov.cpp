#include <verity/stats/kolmogorov_smirnov.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace verity::validation {

double kolmogorovSurvival(double lambda) {
  if (lambda <= 0) return 1;
  constexpr double kPi = 3.14159265358979323846;
  if (lambda < 1.18) {
    // The alternating series converges slowly for small λ; use the Jacobi-theta form of the
    // distribution function, K(λ) = √(2π)/λ Σ_{k≥1} exp(−(2k − 1)² π² / (8 λ²)).
    const double y = std::exp(-kPi * kPi / (8 * lambda * lambda));
    double sum = 0, term = 0;
    for (int k = 1; k <= 100; ++k) {
      term = std::pow(y, double((2 * k - 1) * (2 * k - 1)));
      sum += term;
      if (term < 1e-17 * sum) break;
    }
    return std::clamp(1 - std::sqrt(2 * kPi) / lambda * sum, 0.0, 1.0);
  }
  double sum = 0;
  for (int k = 1; k <= 100; ++k) {
    const double term = std::exp(-2.0 * k * k * lambda * lambda);
    sum += (k % 2 ? 1 : -1) * term;
    if (term < 1e-17) break;
  }
  return std::clamp(2 * sum, 0.0, 1.0);
}

KsResult ksTestUniform(std::vector<double> values) {
  for (double v : values)
    if (!(v >= 0 && v <= 1)) throw std::invalid_argument("ksTestUniform: value not in [0, 1]");
  KsResult r;
  r.n = static_cast<int>(values.size());
  if (r.n == 0) return r;
  std::sort(values.begin(), values.end());
  const double n = r.n;
  double d = 0;
  for (int i = 0; i < r.n; ++i) d = std::max({d, (i + 1) / n - values[i], values[i] - i / n});
  r.statistic = d;
  const double sn = std::sqrt(n);
  r.pValue = kolmogorovSurvival((sn + 0.12 + 0.11 / sn) * d);
  return r;
}

}  // namespace verity::validation
