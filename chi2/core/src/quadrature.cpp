#include <tbb/parallel_for.h>
#include <verity/chi2/batched_density.h>
#include <verity/chi2/quadrature.h>

#include <algorithm>
#include <bit>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

namespace verity::chi2 {

namespace {

using Kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;
using Gauss = boost::math::quadrature::gauss<double, 7>;

// A value of the integrand with the error it carries: the inner integral of a nested
// quadrature, and that integral's own error estimate.
struct Sample {
  double value = 0, error = 0;
};

// One 15-point Gauss–Kronrod rule on [a, b]. `value` and `error` are bit for bit Boost's
// gauss_kronrod<double, 15>::integrate(f, a, b, 0, 0, &error) (Boost 1.74-1.83,
// integrate_non_adaptive_m1_1: the same nodes, weights and order of summation), so every
// refinement decision is the one Boost's figures gave; `error` is therefore max(|K15 − G7|,
// 2ε|K15|) on the rule's own [−1, 1], not yet multiplied by the half-width. `carried` is the
// integrand's own error integrated by the same Kronrod rule (its weights are positive): for
// a nested integral, ∫ |inner error| dx over the piece.
struct Rule {
  double value = 0, error = 0, carried = 0;
};

template <class F>
Rule kronrod(const F& f, double a, double b) {
  const double mean = (b + a) / 2, scale = (b - a) / 2;
  const auto& x = Kronrod::abscissa();
  const auto& wk = Kronrod::weights();
  const auto& wg = Gauss::weights();
  Sample s = f(scale * 0.0 + mean);
  double k = s.value * wk[0], g = s.value * wg[0], c = s.error * wk[0];
  // The Gauss nodes (even indices), then the Kronrod extension (odd), as Boost sums them.
  for (unsigned i = 2; i < x.size(); i += 2) {
    const Sample p = f(scale * x[i] + mean), m = f(scale * -x[i] + mean);
    k += (p.value + m.value) * wk[i];
    g += (p.value + m.value) * wg[i / 2];
    c += (p.error + m.error) * wk[i];
  }
  for (unsigned i = 1; i < x.size(); i += 2) {
    const Sample p = f(scale * x[i] + mean), m = f(scale * -x[i] + mean);
    k += (p.value + m.value) * wk[i];
    c += (p.error + m.error) * wk[i];
  }
  Rule r;
  r.value = scale * k;
  r.error = std::max(std::fabs(k - g), std::fabs(k * std::numeric_limits<double>::epsilon() * 2));
  r.carried = scale * c;
  return r;
}

// Where a 1D integral's error lies: its own rule's estimates and the error its integrand
// carried (both in the integral's units).
struct Errors {
  double rule = 0, carried = 0;
};

// Bisection with the 15-point Gauss–Kronrod rule on each piece. A piece is accepted once
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
// what it reports is scaled to the integral's own units. The error an integrand carries
// (an inner integral's) is summed over the accepted pieces only, each piece's by its own
// Kronrod weights: the integral of that error over x, not a mean over the calls.
template <class F>
double bisect(const F& f, double a, double b, const Rule& whole, double tolerancePerWidth,
              unsigned depth, Errors* errors) {
  if (depth == 0 || whole.error <= tolerancePerWidth * (b - a)) {
    errors->rule += whole.error * (b - a) / 2;
    errors->carried += whole.carried;
    return whole.value;
  }
  const double m = 0.5 * (a + b);
  const Rule r0 = kronrod(f, a, m), r1 = kronrod(f, m, b);
  const double e0 = r0.error, e1 = r1.error;
  // Round-off detection (as in QUADPACK's QAG, Piessens et al. 1983): bisection shrinks the
  // error of a smooth piece many times and that of a jump by half, but leaves the
  // staircase of a density evaluated in single precision as large as it was. Refining
  // noise buys nothing; accept the halves. A jump, a kink or a lobe that the halves find
  // and the whole missed can raise the error too, but it sits in one half (the halves'
  // errors are unequal) or moves the estimate by more than its error.
  const bool noise = e0 + e1 > 0.8 * whole.error && std::min(e0, e1) > 0.25 * std::max(e0, e1) &&
                     std::fabs(r0.value + r1.value - whole.value) <= 2 * whole.error;
  if (noise) {
    errors->rule += (e0 + e1) * (b - a) / 4;
    errors->carried += r0.carried + r1.carried;
    return r0.value + r1.value;
  }
  return bisect(f, a, m, r0, tolerancePerWidth, depth - 1, errors) +
         bisect(f, m, b, r1, tolerancePerWidth, depth - 1, errors);
}

// The adaptive integral of an integrand that returns a Sample, to max(relTolerance·|∫f|,
// absTolerance).
template <class F>
double adaptive(const F& f, double a, double b, const QuadratureOptions& options,
                double absTolerance, Errors* errors) {
  if (!(b > a)) return 0;
  const Rule whole = kronrod(f, a, b);
  const double tolerance = std::max(options.relTolerance * std::fabs(whole.value), absTolerance);
  return bisect(f, a, b, whole, tolerance / (b - a), options.maxDepth, errors);
}

}  // namespace

double integrate1D(const std::function<double(double)>& f, double a, double b,
                   const QuadratureOptions& options, double* error, double absTolerance) {
  Errors errors;
  const double value = adaptive(
      [&](double x) {
        return Sample{f(x), 0};
      },
      a, b, options, absTolerance, &errors);
  if (error) *error = errors.rule;
  return value;
}

namespace {

// The last words of subKey: the options.
constexpr int kOptionWords = 8;

// What a sub-computation of the nested integral depends on besides f: its kind, the domain
// and features it was given (by address: fixed within a computation), its bounds and options.
BatchedDensity::Lookup::Key subKey(int kind, const void* domain, const void* features, double x,
                                   double x0, double x1, double y0, double y1,
                                   const QuadratureOptions& o) {
  auto bits = [](double v) { return std::bit_cast<uint64_t>(v); };
  return {static_cast<uint64_t>(kind),
          reinterpret_cast<uintptr_t>(domain),
          reinterpret_cast<uintptr_t>(features),
          bits(x),
          bits(x0),
          bits(x1),
          bits(y0),
          bits(y1),
          bits(o.relTolerance),
          bits(o.outerRelTolerance),
          bits(o.cellAbsTolerance),
          o.maxDepth};
}

// compute(g), a {value, error}, g being the density to call: f itself, or through a batched
// density (batched_density.h) the sub-computation's own points, so that a pass searches
// among those only and takes a sub-computation an earlier pass finished as it was.
// The key is made only then: the point-by-point path pays one type test.
template <class T, class Key, class Compute>
T remembered(const DensityFn& f, const Key& key, const Compute& compute) {
  const auto* lookup = f.target<BatchedDensity::Lookup>();
  if (!lookup) return compute(f);
  const BatchedDensity::Lookup::Key k = key();
  // The same bounds at other tolerances integrate the same points.
  BatchedDensity::Lookup::Key points = k;
  std::fill(points.begin() + kOptionWords, points.end(), 0);
  const auto r = lookup->remembered(k, points, [&](const DensityFn& g) {
    const T t = compute(g);
    return BatchedDensity::Lookup::Result{t.value, t.error};
  });
  return T{r.value, r.error};
}

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
// `features` identifies breaks, xBreaks and the features that peaks were chosen from.
CellIntegral nested(const DensityFn& f, const BreakpointFn& breaks,
                    const std::vector<double>& xBreaks, const std::vector<Point2d>& peaks,
                    const Domain* domain, const DensityFeatures* features, double x0, double x1,
                    double y0, double y1, const QuadratureOptions& options) {
  // The inner integral at x with its error estimate, which the outer rule integrates over x
  // with its own weights (the nested rule's error is at most the outer rule's error plus
  // ∫ |inner error| dx). An unweighted mean over the calls would count a call on a piece
  // graded 10⁻⁷ of a cell wide, next to a peak or a jump, as much as one on a whole cell.
  auto integrateInner = [&](const DensityFn& g, double x) {
    double lo = y0, hi = y1;
    if (domain) std::tie(lo, hi) = domain->clipY(x, y0, y1);
    if (!(hi > lo)) return Sample{};
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
    Sample s;
    for (size_t k = 0; k + 1 < ys.size(); ++k) {
      Errors err;
      // The cell's absolute budget, spread over y; an inner error enters the cell times its
      // width.
      const double absTolerance =
          options.cellAbsTolerance * (ys[k + 1] - ys[k]) / ((y1 - y0) * (x1 - x0));
      s.value += adaptive(
          [&](double y) {
            return Sample{g(x, y), 0};
          },
          ys[k], ys[k + 1], options, absTolerance, &err);
      s.error += err.rule;
    }
    return s;
  };
  auto inner = [&](double x) {
    return remembered<Sample>(
        f, [&] { return subKey(0, domain, features, x, x0, x1, y0, y1, options); },
        [&](const DensityFn& g) { return integrateInner(g, x); });
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
    Errors err;
    result.value += adaptive(inner, xs[k], xs[k + 1], outer,
                             options.cellAbsTolerance * (xs[k + 1] - xs[k]) / (x1 - x0), &err);
    result.error += err.rule + err.carried;
  }
  return result;
}

}  // namespace

double integrate2D(const DensityFn& f, double x0, double x1, double y0, double y1,
                   const QuadratureOptions& options, double* error) {
  const CellIntegral r = nested(f, {}, {}, {}, nullptr, nullptr, x0, x1, y0, y1, options);
  if (error) *error = r.error;
  return r.value;
}

CellIntegral integrateRectangle(const DensityFn& f, const DensityFeatures& features,
                                const Domain& d, const CellBounds& b,
                                const QuadratureOptions& options) {
  const double w = b.x1 - b.x0, h = b.y1 - b.y0;
  // The peaks that matter here: inside the rectangle or within half its size of it, whose
  // tail would otherwise sit at an end of an interval as a spike. A strip far longer than
  // wide (equal-probability cells, partition.h) reaches an eighth of its length across: a
  // lobe wider than the strip still needs its narrow profile along it graded (measured: a
  // Gaussian of σ = 10⁻³, 0.6σ beside a strip 5·10⁻⁴ wide, integrated to 10⁻²⁶ for 0.16).
  // A grid cell (sides within a factor 4) keeps half its size.
  const double marginX = std::max(w, h / 4) / 2, marginY = std::max(h, w / 4) / 2;
  std::vector<Point2d> near;
  const bool sphere = d.kind == DomainKind::Sphere;
  for (const Point2d& p : features.peaks)
    // φ means nothing at a pole: a peak within a cell of it is graded there (the grid's
    // cell height for a rectangle taller than a cell: a strip of the inversion).
    if (!(sphere && std::fabs(p.y()) > 1 - std::min(h, d.cellHeight())) && p.x() > b.x0 - marginX &&
        p.x() < b.x1 + marginX && p.y() > b.y0 - marginY && p.y() < b.y1 + marginY)
      near.push_back(p);
  return remembered<CellIntegral>(
      f, [&] { return subKey(1, &d, &features, 0, b.x0, b.x1, b.y0, b.y1, options); },
      [&](const DensityFn&) {
        return nested(f, features.breaksY, features.breaksX, near, &d, &features, b.x0, b.x1, b.y0,
                      b.y1, options);
      });
}

CellIntegral integrateCell(const DensityFn& f, const DensityFeatures& features, const Domain& d,
                           int cell, const QuadratureOptions& options) {
  const CellBounds bounds = d.cell(cell);
  // A pilot estimate (one Kronrod rule per piece) sets the cell's share of the grid's
  // absolute error budget as a relative tolerance.
  QuadratureOptions pilot = options;
  pilot.maxDepth = 0;
  const double estimate = std::fabs(integrateRectangle(f, features, d, bounds, pilot).value);
  const double share = options.gridAbsTolerance / d.cells();
  QuadratureOptions o = options;
  o.cellAbsTolerance = share;
  if (estimate > 0) {
    const double rel = share / estimate;
    o.relTolerance = std::clamp(rel, options.relTolerance, options.maxRelTolerance);
    o.outerRelTolerance = std::clamp(10 * rel, options.outerRelTolerance, options.maxRelTolerance);
    // What the cell may be off by, in absolute terms, whatever its pieces' sizes.
    o.cellAbsTolerance = o.relTolerance * estimate;
  }
  const CellIntegral coarse = integrateRectangle(f, features, d, bounds, o);
  // A large cell (relTolerance of its value above its share) that met relTolerance is as
  // accurate as a density evaluated in single precision allows: a second level would only
  // refine rounding steps (it took over half the rules of a rough dielectric's grid).
  if (options.verifyDepth == 0 || !(coarse.error > std::max(share, o.cellAbsTolerance)))
    return coarse;
  // The cell missed its tolerance. Either a feature is not yet resolved, or the
  // density is a staircase of single-precision rounding steps (grazing Beckmann and GGX,
  // tiny roughness, the cancellation in ωi + ωo near −ωi): then every piece's |K15 − G7|
  // stays at the steps' size however far it is bisected, and the sum counts their errors,
  // of either sign, in absolute value (10⁻⁴ and more of a cell whose value moves by 10⁻⁷
  // when refined). So compare two refinement levels: integrate again with every piece
  // bisected verifyDepth more times and tolerances ten times tighter, and keep the finer
  // value. Where the refinement converges (the finer error at most half the coarser), the
  // finer value's error is at most the change |fine − coarse|; its own Gauss–Kronrod
  // estimate is the other bound, and the smaller of the two is reported. This is a
  // heuristic, as Gauss–Kronrod's own estimate is: a feature that the deeper level begins
  // to resolve moves the value and keeps the estimate up, but a lobe narrower than both
  // levels' pieces and not declared (Subject::peaks) can escape both, as it escapes any
  // rule (FrameworkQuadratureBounds tests the shapes the subjects have).
  QuadratureOptions fine = o;
  fine.maxDepth += options.verifyDepth;
  fine.relTolerance /= 10;
  fine.outerRelTolerance /= 10;
  fine.cellAbsTolerance /= 10;
  const CellIntegral r = integrateRectangle(f, features, d, bounds, fine);
  return {r.value, std::min(r.error, std::fabs(r.value - coarse.value))};
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
