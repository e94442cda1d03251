#include <verity/stats/power.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace verity::validation {

namespace {

// Double precision throughout: Boost's default promotion to long double is several times
// slower and p-values need no more than double.
using Policy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
using StudentsT = boost::math::students_t_distribution<double, Policy>;
using Normal = boost::math::normal_distribution<double, Policy>;

bool isNormal(double df) {
  return std::isinf(df) || df > 1e7;
}

// The terms that carry noise, each with its two-sided critical value at `level` (computed
// once: the quantile is the expensive part).
struct Prepared {
  double effect;  // M / √V: δ = r · effect
  double df;
  double critical;  // c
  int group;
};

std::vector<Prepared> prepare(const std::vector<PowerTerm>& terms, int m, double alpha) {
  if (m < 1 || !(alpha > 0 && alpha < 1))
    throw std::invalid_argument("power: needs m >= 1 and alpha in (0, 1)");
  const double half = alpha / m / 2;
  const Normal normal;
  const double zc = boost::math::quantile(boost::math::complement(normal, half));
  std::vector<Prepared> out;
  for (const PowerTerm& t : terms) {
    if (!(t.variance > 0) || !(t.df > 0)) continue;
    const double c =
        isNormal(t.df) ? zc : boost::math::quantile(boost::math::complement(StudentsT(t.df), half));
    out.push_back({t.mean / std::sqrt(t.variance), t.df, c, t.group});
  }
  return out;
}

// P(|δ + T_ν| > c).
double passProbability(const Prepared& p, double r) {
  const double delta = r * p.effect;
  if (isNormal(p.df)) {
    const Normal n;
    return boost::math::cdf(boost::math::complement(n, p.critical - delta)) +
           boost::math::cdf(n, -p.critical - delta);
  }
  const StudentsT t(p.df);
  return boost::math::cdf(boost::math::complement(t, p.critical - delta)) +
         boost::math::cdf(t, -p.critical - delta);
}

double probability(const std::vector<Prepared>& prepared, double r) {
  std::map<int, double> logMiss;  // per group: sum of log(1 - P_j)
  for (const Prepared& p : prepared) {
    const double pass = std::clamp(passProbability(p, r), 0.0, 1.0);
    logMiss[p.group] += std::log1p(-std::min(pass, 1 - 1e-16));
  }
  double best = 0;
  for (const auto& [group, lm] : logMiss) best = std::max(best, -std::expm1(lm));
  return best;
}

}  // namespace

double rejectionProbability(const std::vector<PowerTerm>& terms, int m, double alpha, double r) {
  return probability(prepare(terms, m, alpha), r);
}

double detectableRelativeBias(const std::vector<PowerTerm>& terms, int m, double alpha,
                              double power) {
  if (!(power > 0 && power < 1))
    throw std::invalid_argument("detectableRelativeBias: power not in (0, 1)");
  const std::vector<Prepared> prepared = prepare(terms, m, alpha);
  double lo = 0, hi = 100;
  if (probability(prepared, hi) < power) return std::numeric_limits<double>::infinity();
  while (hi - lo > 1e-6 * hi) {
    const double mid = 0.5 * (lo + hi);
    (probability(prepared, mid) >= power ? hi : lo) = mid;
  }
  return hi;
}

}  // namespace verity::validation
