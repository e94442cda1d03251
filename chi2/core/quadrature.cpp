#include "quadrature.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

namespace verity::chi2 {

using Kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;

namespace {

// Bisection with Boost's 15-point Gauss–Kronrod rule on each piece. A piece is accepted once
// its error estimate is within its share, by width, of the interval's tolerance, or once
// bisection stops reducing it. Boost's own
// recursion tolerates only a fraction of the piece's own integral, which a piece a few ulps
// wide, or a density evaluated in single precision (a staircase at fine scales), never
// meets: each such piece would be refined to the maximum depth.
//
// Boost reports a finite interval's error |K15 − G7| on the rule's own interval [−1, 1], not
// multiplied by the half-width (b − a)/2 as the integral is (Boost 1.74-1.83,
// recursive_adaptive_integrate): on [0, 0.02], √x gets an estimate of 6.6e-5 against a true
// error of 3.8e-8. The refinement below compares those unscaled figures, as it was tuned to;
// what it reports, `errorSum`, is scaled to the integral's own units.
double bisect(const std::function<double(double)>& f, double a, double b, double value,
              double error, double tolerancePerWidth, unsigned depth, double* errorSum) {
  if (depth == 0 || error <= tolerancePerWidth * (b - a)) {
    *errorSum += error * (b - a) / 2;
    return value;
  }
  const double m = 0.5 * (a + b);
  double e0 = 0, e1 = 0;
  const double v0 = Kronrod::integrate(f, a, m, 0, 0, &e0);
  const double v1 = Kronrod::integrate(f, m, b, 0, 0, &e1);
  // Round-off detection (as in QUADPACK's QAG, Piessens et al. 1983): bisection shrinks the
  // error of a smooth piece many times and that of a jump by half, but leaves the
  // staircase of a density evaluated in single precision as large as it was. Refining
  // noise buys nothing; accept the halves. A jump, a kink or a lobe that the halves find
  // and the whole missed can raise the error too, but it sits in one half (the halves'
  // errors are unequal) or moves the estimate by more than its error.
  const bool noise = e0 + e1 > 0.8 * error && std::min(e0, e1) > 0.25 * std::max(e0, e1) &&
                     std::fabs(v0 + v1 - value) <= 2 * error;
  if (noise) {
    *errorSum += (e0 + e1) * (b - a) / 4;
    return v0 + v1;
  }
  return bisect(f, a, m, v0, e0, tolerancePerWidth, depth - 1, errorSum) +
         bisect(f, m, b, v1, e1, tolerancePerWidth, depth - 1, errorSum);
}

}  // namespace

double integrate1D(const std::function<double(double)>& f, double a, double b,
                   const QuadratureOptions& options, double* error, double absTolerance) {
  if (!(b > a)) {
    if (error) *error = 0;
    return 0;
  }
  double err = 0, sum = 0;
  const double value = Kronrod::integrate(f, a, b, 0, 0, &err);
  const double tolerance = std::max(options.relTolerance * std::fabs(value), absTolerance);
  const double result = bisect(f, a, b, value, err, tolerance / (b - a), options.maxDepth, &sum);
  if (error) *error = sum;
  return result;
}

namespace {

// Cuts at centre ± width·10⁻ᵏ (k = 0 … 7) and at centre itself, those inside (lo, hi): a peak
// at `centre` far narrower than any bisection of the interval is then resolved, each piece
// holding a part of it of about its own size (geometric hp-refinement). The densities are
// evaluated in single precision, so structure finer than ~10⁻⁷ of a cell cannot be
// resolved; finer pieces, a few ulps wide, only defeat the adaptive rule's convergence test.
void addGradedCuts(double centre, double width, double lo, double hi, std::vector<double>& cuts) {
  for (double gap = width; gap >= width * 1e-7; gap *= 0.1)
    for (double c : {centre - gap, centre + gap})
      if (c > lo && c < hi) cuts.push_back(c);
  if (centre > lo && centre < hi) cuts.push_back(centre);
}

// [lo, hi] split at the cuts, in order.
std::vector<double> pieces(double lo, double hi, std::vector<double> cuts) {
  cuts.push_back(lo);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

// ∫∫ f over [x0,x1] × clipY(x, y0, y1): the inner limits follow the domain's support, so the
// boundary of the disk or triangle is a limit of integration and not a discontinuity. The
// outer and inner ranges are split at the peaks inside the cell, graded towards them.
CellIntegral nested(const DensityFn& f, const BreakpointFn& breaks,
                    const std::vector<double>& xBreaks, const std::vector<Point2d>& peaks,
                    const Domain* domain, double x0, double x1, double y0, double y1,
                    const QuadratureOptions& options) {
  double innerErrorSum = 0;
  int innerCalls = 0;
  auto inner = [&](double x) {
    double lo = y0, hi = y1;
    if (domain) std::tie(lo, hi) = domain->clipY(x, y0, y1);
    if (!(hi > lo)) return 0.0;
    // Split the y range at the density's jumps.
    std::vector<double> cuts;
    if (breaks)
      for (double b : breaks(x))
        if (b > lo && b < hi) cuts.push_back(b);
    for (const Point2d& p : peaks) addGradedCuts(p.y(), y1 - y0, lo, hi, cuts);
    // On the sphere, a lobe around a pole (normal incidence, tiny roughness, an index near
    // 1) is a peak of width ~θ²/2 in cos θ at y = ±1.
    if (domain && domain->kind == DomainKind::Sphere)
      for (double pole : {-1.0, 1.0}) addGradedCuts(pole, 1.0, lo, hi, cuts);
    const std::vector<double> ys = pieces(lo, hi, std::move(cuts));
    double v = 0;
    for (size_t k = 0; k + 1 < ys.size(); ++k) {
      double err = 0;
      // The cell's absolute budget, spread over y; an inner error enters the cell times its
      // width.
      const double absTolerance =
          options.cellAbsTolerance * (ys[k + 1] - ys[k]) / ((y1 - y0) * (x1 - x0));
      v += integrate1D([&](double y) { return f(x, y); }, ys[k], ys[k + 1], options, &err,
                       absTolerance);
      innerErrorSum += err;
    }
    ++innerCalls;
    return v;
  };
  std::vector<double> xCuts;
  for (double b : xBreaks)
    if (b > x0 && b < x1) xCuts.push_back(b);
  for (const Point2d& p : peaks) addGradedCuts(p.x(), x1 - x0, x0, x1, xCuts);
  const std::vector<double> xs = pieces(x0, x1, std::move(xCuts));
  CellIntegral result;
  QuadratureOptions outer = options;
  outer.relTolerance = options.outerRelTolerance;
  for (size_t k = 0; k + 1 < xs.size(); ++k) {
    double outerError = 0;
    result.value += integrate1D(inner, xs[k], xs[k + 1], outer, &outerError,
                                options.cellAbsTolerance * (xs[k + 1] - xs[k]) / (x1 - x0));
    result.error += outerError;
  }
  if (innerCalls) result.error += (x1 - x0) * innerErrorSum / innerCalls;
  return result;
}

}  // namespace

double integrate2D(const DensityFn& f, double x0, double x1, double y0, double y1,
                   const QuadratureOptions& options, double* error) {
  const CellIntegral r = nested(f, {}, {}, {}, nullptr, x0, x1, y0, y1, options);
  if (error) *error = r.error;
  return r.value;
}

CellIntegral integrateCell(const DensityFn& f, const DensityFeatures& features, const Domain& d,
                           int cell, const QuadratureOptions& options) {
  const int i = cell % d.nx, j = cell / d.nx;
  const double w = d.cellWidth(), h = d.cellHeight();
  const double x0 = d.x0 + i * w, y0 = d.y0 + j * h;
  // The peaks that matter here: inside the cell or within half a cell of it, whose tail
  // would otherwise sit at an end of an interval as a spike.
  std::vector<Point2d> near;
  const bool sphere = d.kind == DomainKind::Sphere;
  for (const Point2d& p : features.peaks)
    if (!(sphere && std::fabs(p.y()) > 1 - h) &&  // φ means nothing at a pole: graded there
        p.x() > x0 - w / 2 && p.x() < x0 + 1.5 * w && p.y() > y0 - h / 2 && p.y() < y0 + 1.5 * h)
      near.push_back(p);
  // A pilot estimate (one Kronrod rule per piece) sets the cell's share of the grid's
  // absolute error budget as a relative tolerance.
  QuadratureOptions pilot = options;
  pilot.maxDepth = 0;
  const double estimate = std::fabs(
      nested(f, features.breaksY, features.breaksX, near, &d, x0, x0 + w, y0, y0 + h, pilot).value);
  QuadratureOptions o = options;
  o.cellAbsTolerance = options.gridAbsTolerance / d.cells();
  if (estimate > 0) {
    const double rel = options.gridAbsTolerance / d.cells() / estimate;
    o.relTolerance = std::clamp(rel, options.relTolerance, options.maxRelTolerance);
    o.outerRelTolerance = std::clamp(10 * rel, options.outerRelTolerance, options.maxRelTolerance);
    // What the cell may be off by, in absolute terms, whatever its pieces' sizes.
    o.cellAbsTolerance = o.relTolerance * estimate;
  }
  return nested(f, features.breaksY, features.breaksX, near, &d, x0, x0 + w, y0, y0 + h, o);
}

std::vector<CellIntegral> integrateGrid(const DensityFn& f, const Domain& domain,
                                        const QuadratureOptions& options,
                                        const DensityFeatures& features) {
  std::vector<CellIntegral> cells(domain.cells());
  tbb::parallel_for(0, domain.cells(),
                    [&](int c) { cells[c] = integrateCell(f, features, domain, c, options); });
  return cells;
}

}  // namespace verity::chi2
