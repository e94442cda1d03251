#include "validation/studies/fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

namespace verity::studies {

LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y, double confidence) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  LineFit fit;
  fit.confidence = confidence;
  std::vector<std::pair<double, double>> points;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (std::isfinite(x[i]) && std::isfinite(y[i])) points.emplace_back(x[i], y[i]);
  fit.n = int(points.size());
  fit.slope = fit.intercept = fit.slopeStdError = fit.slopeLow = fit.slopeHigh = nan;
  fit.residualStd = nan;
  if (fit.n < 2) return fit;

  Eigen::MatrixXd design(fit.n, 2);
  Eigen::VectorXd rhs(fit.n);
  for (int i = 0; i < fit.n; ++i) {
    design(i, 0) = 1;
    design(i, 1) = points[i].first;
    rhs(i) = points[i].second;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < 2) return fit;  // every x the same
  const Eigen::Vector2d beta = qr.solve(rhs);
  fit.intercept = beta(0);
  fit.slope = beta(1);
  if (fit.n < 3) return fit;

  const double dof = fit.n - 2;
  const double s2 = (design * beta - rhs).squaredNorm() / dof;
  const double meanX = design.col(1).mean();
  const double sxx = (design.col(1).array() - meanX).square().sum();
  fit.residualStd = std::sqrt(s2);
  fit.slopeStdError = std::sqrt(s2 / sxx);
  const boost::math::students_t t(dof);
  const double q = boost::math::quantile(t, 0.5 + confidence / 2);
  fit.meanX = meanX;
  fit.sxx = sxx;
  fit.tQuantile = q;
  fit.slopeLow = fit.slope - q * fit.slopeStdError;
  fit.slopeHigh = fit.slope + q * fit.slopeStdError;
  return fit;
}

LineFit fitLogLog(const std::vector<double>& x, const std::vector<double>& y, double confidence) {
  std::vector<double> lx, ly;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
      lx.push_back(std::log(x[i]));
      ly.push_back(std::log(y[i]));
    }
  return fitLine(lx, ly, confidence);
}

Crossing crossing(const LineFit& fit, double y) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  Crossing c{nan, nan, nan, false};
  if (!std::isfinite(fit.slope) || fit.slope == 0) return c;
  c.x = (y - fit.intercept) / fit.slope;
  if (!std::isfinite(fit.slopeStdError) || !(fit.sxx > 0)) return c;
  // With d = x − x̄ and e = y − ŷ(x̄), the band's edges solve
  // (slope² − t²s²/Sxx) d² − 2·slope·e·d + (e² − t²s²/n) = 0.
  const double ts2 = fit.tQuantile * fit.tQuantile * fit.residualStd * fit.residualStd;
  const double e = y - (fit.intercept + fit.slope * fit.meanX);
  const double a = fit.slope * fit.slope - ts2 / fit.sxx;
  if (!(a > 0)) return c;  // the slope is not significant: the interval is unbounded
  const double b = fit.slope * e;
  const double root = std::sqrt(std::max(0.0, b * b - a * (e * e - ts2 / fit.n)));
  c.low = fit.meanX + (b - root) / a;
  c.high = fit.meanX + (b + root) / a;
  c.bounded = true;
  return c;
}

double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

}  // namespace verity::studies
