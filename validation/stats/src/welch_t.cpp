#include <verity/stats/welch_t.h>

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace verity::validation {

namespace {

// Double precision throughout: Boost's default promotion to long double is several times
// slower and p-values need no more than double.
using Policy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;
using StudentsT = boost::math::students_t_distribution<double, Policy>;

void check(const MeanEstimate& e, const char* which) {
  if (!std::isfinite(e.mean) || !std::isfinite(e.variance) || !std::isfinite(e.dfDenominator) ||
      e.variance < 0 || e.dfDenominator < 0)
    throw std::invalid_argument(std::string("welchTest: invalid estimate ") + which);
}

}  // namespace

MeanEstimate sampleMean(double mean, double sampleVariance, double n) {
  if (!(n >= 2)) throw std::invalid_argument("sampleMean: needs at least two samples");
  const double v = sampleVariance / n;
  return {mean, v, v * v / (n - 1)};
}

WelchResult welchTest(const MeanEstimate& a, const MeanEstimate& b) {
  check(a, "A");
  check(b, "B");
  WelchResult r;
  const double v = a.variance + b.variance;
  if (v == 0) {
    r.deterministic = true;
    r.df = std::numeric_limits<double>::infinity();
    r.p = a.mean == b.mean ? 1.0 : 0.0;
    return r;
  }
  r.t = (b.mean - a.mean) / std::sqrt(v);
  const double denominator = a.dfDenominator + b.dfDenominator;
  // A positive variance with a zero denominator would need infinitely many samples; treat
  // it as the normal limit.
  r.df = denominator > 0 ? v * v / denominator : std::numeric_limits<double>::infinity();
  if (std::isinf(r.df) || r.df > 1e12) {
    r.p = std::erfc(std::abs(r.t) / std::sqrt(2.0));
  } else {
    const StudentsT dist(r.df);
    r.p = 2 * boost::math::cdf(boost::math::complement(dist, std::abs(r.t)));
  }
  r.p = std::min(r.p, 1.0);
  return r;
}

}  // namespace verity::validation
