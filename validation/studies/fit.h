// Straight-line fits of log error against log cost, with confidence intervals.
#pragma once

#include <vector>

namespace verity::studies {

struct LineFit {
  int n = 0;  // points used (finite, positive x and y)
  double slope = 0, intercept = 0;
  double slopeStdError = 0;            // NaN below three points
  double slopeLow = 0, slopeHigh = 0;  // two-sided confidence interval of the slope
  double confidence = 0.95;
  double residualStd = 0;     // standard deviation of the residuals (n − 2 degrees of freedom)
  double meanX = 0, sxx = 0;  // x̄ and Σ (xᵢ − x̄)², for intervals at other x
  double tQuantile = 0;       // the Student-t quantile of the intervals
};

// Where the fitted line reaches y: the point estimate x₀ = (y − intercept) / slope and the
// inverse-prediction (calibration) interval of the x at which the line's MEAN is y: the x
// whose confidence band of the mean, ŷ(x) ± t·s·√(1/n + (x − x̄)²/Sxx), contains y (Fieller's
// theorem; Draper & Smith, "Applied Regression Analysis", 3rd ed., section 3.2, "Inverse
// regression (the calibration problem)"). The interval is bounded only when the slope
// differs from 0 at the fit's confidence (g = (t·se/slope)² < 1); otherwise it is unbounded and
// `bounded` is false.
struct Crossing {
  double x = 0, low = 0, high = 0;
  bool bounded = false;
};
Crossing crossing(const LineFit& fit, double y);

// Ordinary least squares of y on x (Eigen's Householder QR). The slope's standard error is
// s / sqrt(Σ (xᵢ − x̄)²) with s² = Σ residual² / (n − 2), and its interval is slope ± t·se with t
// the (1 + confidence)/2 quantile of Student's t with n − 2 degrees of freedom
// (boost::math::students_t); e.g. Montgomery & Runger, "Applied Statistics and Probability
// for Engineers", section 11-4; NIST/SEMATECH e-Handbook of Statistical Methods, 4.1.4.
// Exact under independent Gaussian errors of constant variance.
LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y,
                double confidence = 0.95);
// The same fit of log(y) on log(x) (natural logarithms; the slope is base-independent),
// leaving out points with x ≤ 0 or y ≤ 0.
LineFit fitLogLog(const std::vector<double>& x, const std::vector<double>& y,
                  double confidence = 0.95);

// The middle value, or the mean of the two middle values of an even count; NaN for an empty
// vector (a statistic of no runs is no number, never an out-of-range read).
double median(std::vector<double> v);

}  // namespace verity::studies
