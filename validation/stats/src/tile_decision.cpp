#include <verity/stats/power.h>
#include <verity/stats/tile_decision.h>

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace verity::validation {

namespace {

double relativeDifference(double a, double b) {
  const double scale = 0.5 * (std::abs(a) + std::abs(b));
  return scale > 0 ? (b - a) / scale : 0.0;
}

// Φ⁻¹(1 − p/2), signed like b − a.
double zScore(const TileTest& t) {
  const double sign = t.pooled.b.mean >= t.pooled.a.mean ? 1.0 : -1.0;
  if (t.welch.p <= 0) return sign * std::numeric_limits<double>::infinity();
  if (t.welch.p >= 1) return 0.0;
  const boost::math::normal normal;
  return sign * boost::math::quantile(boost::math::complement(normal, t.welch.p / 2));
}

PowerTerm powerTerm(const TileTest& t, int group) {
  return {0.5 * (t.pooled.a.mean + t.pooled.b.mean), t.pooled.a.variance + t.pooled.b.variance,
          t.welch.df, group};
}

}  // namespace

TileDecision decideTiles(std::vector<TileTest>& tests, double alpha, double power,
                         bool detectableBias) {
  constexpr double kNotComputed = std::numeric_limits<double>::quiet_NaN();
  if (tests.empty()) throw std::invalid_argument("decideTiles: no test to decide");
  TileDecision d;
  const int m = static_cast<int>(tests.size());
  std::vector<double> p(tests.size());
  for (size_t i = 0; i < tests.size(); ++i) {
    TileTest& t = tests[i];
    t.welch = welchTest(t.pooled.a, t.pooled.b);
    t.relativeDifference = relativeDifference(t.pooled.a.mean, t.pooled.b.mean);
    t.z = zScore(t);
    t.detectableBias = !detectableBias ? kNotComputed
                       : t.welch.deterministic
                           ? 0.0
                           : detectableRelativeBias({powerTerm(t, 0)}, m, alpha, power);
    d.deterministicTests += t.welch.deterministic;
    p[i] = t.welch.p;
  }
  d.holm = holmBonferroni(p, alpha);
  for (size_t i = 0; i < tests.size(); ++i) {
    tests[i].adjustedP = d.holm.adjusted[i];
    tests[i].rejected = d.holm.rejected[i];
  }
  d.smallestP = *std::min_element(p.begin(), p.end());
  d.differ = d.holm.rejections > 0;

  int channelsTested = 0;
  double smallestKs = 1;
  for (int c = 0; c < kChannels; ++c) {
    std::vector<double> values;
    for (const TileTest& t : tests)
      if (t.channel == c && !t.welch.deterministic) values.push_back(t.welch.p);
    d.uniformity[c] = ksTestUniform(values);
    if (d.uniformity[c].n > 0) {
      ++channelsTested;
      smallestKs = std::min(smallestKs, d.uniformity[c].pValue);
    }
  }
  d.uniformityP = std::min(1.0, channelsTested * smallestKs);

  // Tests of one channel are independent (disjoint pixels): the channel is the power group.
  if (!detectableBias) {
    d.detectableBias = kNotComputed;
    return d;
  }
  std::vector<PowerTerm> terms;
  for (const TileTest& t : tests) terms.push_back(powerTerm(t, t.channel));
  d.detectableBias = detectableRelativeBias(terms, m, alpha, power);
  return d;
}

}  // namespace verity::validation
