#include <verity/chi2/quadrature.h>

#include <algorithm>
#include <array>
#include <bit>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <limits>
#include <tuple>
#include <unordered_map>

#include "quadrature_tasks.h"

namespace verity::chi2 {

namespace {

using Kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;
using Gauss = boost::math::quadrature::gauss<double, 7>;
constexpr size_t kNodes = 15;

// A value of the integrand with the error it carries: the inner integral of a nested
// quadrature, and that integral's own error estimate.
struct Sample {
  double value = 0, error = 0;
};
using Nodes = std::array<double, kNodes>;

// One 15-point Gauss–Kronrod rule on [a, b], from the integrand at kronrodNodes(a, b). `value` and
// `error` are bit for bit Boost's gauss_kronrod<double, 15>::integrate(f, a, b, 0, 0, &error)
// (Boost 1.74-1.83, integrate_non_adaptive_m1_1: the same nodes, weights and order of summation),
// so every refinement decision is the one Boost's figures gave; `error` is therefore max(|K15 −
// G7|, 2ε|K15|) on the rule's own [−1, 1], not yet multiplied by the half-width. `carried` is the
// integrand's own error integrated by the same Kronrod rule (its weights are positive): for
// a nested integral, ∫ |inner error| dx over the piece.
struct Rule {
  double value = 0, error = 0, carried = 0;
};

// The rule's abscissae on [a, b] in the order it sums them: the centre, ± each Gauss node
// (even indices), then ± each node of the Kronrod extension (odd), as Boost sums them.
Nodes kronrodNodes(double a, double b) {
  const double mean = (b + a) / 2, scale = (b - a) / 2;
  const auto& x = Kronrod::abscissa();
  Nodes t;
  size_t n = 0;
  t[n++] = scale * 0.0 + mean;
  for (unsigned i = 2; i < x.size(); i += 2) {
    t[n++] = scale * x[i] + mean;
    t[n++] = scale * -x[i] + mean;
  }
  for (unsigned i = 1; i < x.size(); i += 2) {
    t[n++] = scale * x[i] + mean;
    t[n++] = scale * -x[i] + mean;
  }
  return t;
}

// `at(i)` is the Sample at node i of kronrodNodes(a, b).
template <class At>
Rule kronrodRule(const At& at, double a, double b) {
  const double scale = (b - a) / 2;
  const auto& x = Kronrod::abscissa();
  const auto& wk = Kronrod::weights();
  const auto& wg = Gauss::weights();
  size_t n = 0;
  const Sample centre = at(n++);
  double k = centre.value * wk[0], g = centre.value * wg[0], c = centre.error * wk[0];
  for (unsigned i = 2; i < x.size(); i += 2, n += 2) {
    const Sample p = at(n), m = at(n + 1);
    k += (p.value + m.value) * wk[i];
    g += (p.value + m.value) * wg[i / 2];
    c += (p.error + m.error) * wk[i];
  }
  for (unsigned i = 1; i < x.size(); i += 2, n += 2) {
    const Sample p = at(n), m = at(n + 1);
    k += (p.value + m.value) * wk[i];
    c += (p.error + m.error) * wk[i];
  }
  Rule r;
  r.value = scale * k;
  r.error = std::max(std::fabs(k - g), std::fabs(k * std::numeric_limits<double>::epsilon() * 2));
  r.carried = scale * c;
  return r;
}

// The rules on consecutive pieces [ends[k], ends[k + 1]], `at(i)` being the integrand at their
// nodes in order.
template <size_t Rules, class At>
std::array<Rule, Rules> rulesFrom(const std::array<double, Rules + 1>& ends, const At& at) {
  std::array<Rule, Rules> rules;
  for (size_t k = 0; k < Rules; ++k)
    rules[k] = kronrodRule([&](size_t i) { return at(k * kNodes + i); }, ends[k], ends[k + 1]);
  return rules;
}

// The rules a cell's integrals computed along y, by their x and piece: its pilot estimate, its
// coarse level and its verifying level start from the same pieces, whose densities are then
// evaluated once (half the points of a smooth lobe's grid). Used by one computation at a time.
class RuleMemo {
 public:
  const Rule* find(double x, double a, double b) const {
    const auto it = rules_.find(key(x, a, b));
    return it == rules_.end() ? nullptr : &it->second;
  }
  void keep(double x, double a, double b, const Rule& r) { rules_.emplace(key(x, a, b), r); }

 private:
  using Key = std::array<uint64_t, 3>;
  struct Hash {
    size_t operator()(const Key& k) const {
      uint64_t h = 0xcbf29ce484222325;  // FNV-1a over the words
      for (uint64_t w : k) h = (h ^ w) * 0x100000001b3;
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  static Key key(double x, double a, double b) {
    return {std::bit_cast<uint64_t>(x), std::bit_cast<uint64_t>(a), std::bit_cast<uint64_t>(b)};
  }
  std::unordered_map<Key, Rule, Hash> rules_;
};

// The density along y at one x, the inner integrals' integrand. Its rules are awaiters, not
// computations: the nodes of a rule, or of a piece's two halves, in one request, unless the
// memo has them all.
struct AlongY {
  Density& density;
  double x;
  RuleMemo* memo = nullptr;

  template <size_t Rules>
  struct NodeValues {
    const AlongY& along;
    std::array<double, Rules + 1> ends;
    std::array<Rule, Rules> rules;
    bool remembered = false;
    std::array<Point2d, kNodes * Rules> points;
    std::array<double, kNodes * Rules> values;

    Density::Request request() {
      for (size_t k = 0; k < Rules; ++k) {
        const auto ys = kronrodNodes(ends[k], ends[k + 1]);
        for (size_t i = 0; i < kNodes; ++i) points[k * kNodes + i] = Point2d(along.x, ys[i]);
      }
      return along.density.at(points.data(), values.data(), points.size());
    }
    bool await_ready() {
      if (along.memo) {
        remembered = true;
        for (size_t k = 0; k < Rules && remembered; ++k)
          if (const Rule* r = along.memo->find(along.x, ends[k], ends[k + 1]))
            rules[k] = *r;
          else
            remembered = false;
        if (remembered) return true;
      }
      return request().await_ready();
    }
    void await_suspend(std::coroutine_handle<> waiting) {
      along.density.wait(points.data(), values.data(), points.size(), waiting);
    }
    std::array<Rule, Rules> await_resume() {
      if (remembered) return rules;
      rules = rulesFrom<Rules>(ends, [&](size_t i) { return Sample{values[i], 0}; });
      if (along.memo)
        for (size_t k = 0; k < Rules; ++k)
          along.memo->keep(along.x, ends[k], ends[k + 1], rules[k]);
      return rules;
    }
  };
  // co_await rule(a, b): a Rule; co_await halves(a, m, b): both halves' rules.
  NodeValues<1> rule(double a, double b) const { return {*this, {a, b}}; }
  NodeValues<2> halves(double a, double m, double b) const { return {*this, {a, m, b}}; }
};

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
// A piece's integral and where its error lies.
struct Part {
  double value = 0;
  Errors errors;
};

// Whether a piece is accepted as its rule gives it: within its share of the tolerance, or at
// the greatest depth.
bool accepted(const Rule& r, double a, double b, double tolerancePerWidth, unsigned depth) {
  return depth == 0 || r.error <= tolerancePerWidth * (b - a);
}
Part leaf(const Rule& r, double a, double b) {
  return {r.value, {r.error * (b - a) / 2, r.carried}};
}

// Bisection with the 15-point Gauss–Kronrod rule on each piece (the comment above), of a piece
// its rule did not settle; the halves of a piece, and their own halves, are refined together.
// A half accepted as it is costs no computation of its own.
template <class Integrand>
Task<Part> bisect(Density& d, const Integrand& f, double a, double b, Rule whole,
                  double tolerancePerWidth, unsigned depth) {
  const double m = 0.5 * (a + b);
  const std::array<Rule, 2> halves = co_await f.halves(a, m, b);
  const Rule &r0 = halves[0], &r1 = halves[1];
  const double e0 = r0.error, e1 = r1.error;
  // Round-off detection (as in QUADPACK's QAG, Piessens et al. 1983): bisection shrinks the
  // error of a smooth piece many times and that of a jump by half, but leaves the
  // staircase of a density evaluated in single precision as large as it was. Refining
  // noise buys nothing; accept the halves. A jump, a kink or a lobe that the halves find
  // and the whole missed can raise the error too, but it sits in one half (the halves'
  // errors are unequal) or moves the estimate by more than its error.
  const bool noise = e0 + e1 > 0.8 * whole.error && std::min(e0, e1) > 0.25 * std::max(e0, e1) &&
                     std::fabs(r0.value + r1.value - whole.value) <= 2 * whole.error;
  if (noise)
    co_return Part{r0.value + r1.value, {(e0 + e1) * (b - a) / 4, r0.carried + r1.carried}};
  const bool done0 = accepted(r0, a, m, tolerancePerWidth, depth - 1),
             done1 = accepted(r1, m, b, tolerancePerWidth, depth - 1);
  std::array<Part, 2> p{leaf(r0, a, m), leaf(r1, m, b)};
  if (!done0 && !done1)
    p = co_await d.both(bisect(d, f, a, m, r0, tolerancePerWidth, depth - 1),
                        bisect(d, f, m, b, r1, tolerancePerWidth, depth - 1));
  else if (!done0)
    p[0] = co_await bisect(d, f, a, m, r0, tolerancePerWidth, depth - 1);
  else if (!done1)
    p[1] = co_await bisect(d, f, m, b, r1, tolerancePerWidth, depth - 1);
  co_return Part{p[0].value + p[1].value,
                 {p[0].errors.rule + p[1].errors.rule, p[0].errors.carried + p[1].errors.carried}};
}

// The adaptive integral of an integrand of Samples, to max(relTolerance·|∫f|, absTolerance).
template <class Integrand>
Task<Part> adaptive(Density& d, const Integrand& f, double a, double b, QuadratureOptions options,
                    double absTolerance) {
  if (!(b > a)) co_return Part{};
  const Rule whole = (co_await f.rule(a, b))[0];
  const double tolerance = std::max(options.relTolerance * std::fabs(whole.value), absTolerance);
  const double perWidth = tolerance / (b - a);
  if (accepted(whole, a, b, perWidth, options.maxDepth)) co_return leaf(whole, a, b);
  co_return co_await bisect(d, f, a, b, whole, perWidth, options.maxDepth);
}

}  // namespace

double integrate1D(const std::function<double(double)>& f, double a, double b,
                   const QuadratureOptions& options, double* error, double absTolerance) {
  const DensityFn alongY = [&](double, double y) { return f(y); };
  Density d(alongY);
  const AlongY integrand{d, 0};
  const Part p = d.run(adaptive(d, integrand, a, b, options, absTolerance));
  if (error) *error = p.errors.rule;
  return p.value;
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
struct Nested {
  BreakpointFn breaks;
  std::vector<double> xBreaks;
  std::vector<Point2d> peaks;
  const Domain* domain;
  double x0, x1, y0, y1;
  QuadratureOptions options;
  RuleMemo* memo;
};

// The inner integral at x with its error estimate, which the outer rule integrates over x
// with its own weights (the nested rule's error is at most the outer rule's error plus
// ∫ |inner error| dx). An unweighted mean over the calls would count a call on a piece
// graded 10⁻⁷ of a cell wide, next to a peak or a jump, as much as one on a whole cell.
Task<Sample> innerIntegral(Density& d, const Nested& spec, double x) {
  double lo = spec.y0, hi = spec.y1;
  if (spec.domain) std::tie(lo, hi) = spec.domain->clipY(x, spec.y0, spec.y1);
  if (!(hi > lo)) co_return Sample{};
  // Split the y range at the density's jumps.
  std::vector<double> cuts;
  if (spec.breaks)
    for (double b : spec.breaks(x))
      if (b > lo && b < hi) cuts.push_back(b);
  for (const Point2d& p : spec.peaks) addGradedCuts(p.y(), spec.y1 - spec.y0, lo, hi, cuts);
  // On the sphere, a lobe around a pole (normal incidence, tiny roughness, an index near
  // 1) is a peak of width ~θ²/2 in cos θ at y = ±1.
  if (spec.domain && spec.domain->kind == DomainKind::Sphere)
    for (double pole : {-1.0, 1.0}) addGradedCuts(pole, 1.0, lo, hi, cuts);
  const std::vector<double> ys = pieces(lo, hi, std::move(cuts));
  const AlongY along{d, x, spec.memo};
  auto piece = [&](size_t k) {
    // The cell's absolute budget, spread over y; an inner error enters the cell times its
    // width.
    const double absTolerance = spec.options.cellAbsTolerance * (ys[k + 1] - ys[k]) /
                                ((spec.y1 - spec.y0) * (spec.x1 - spec.x0));
    return adaptive(d, along, ys[k], ys[k + 1], spec.options, absTolerance);
  };
  Sample s;
  auto add = [&](const Part& p) {
    s.value += p.value;
    s.error += p.errors.rule;
  };
  if (ys.size() == 2) {  // one piece, the common case: awaited without the vectors
    add(co_await piece(0));
  } else {
    std::vector<Task<Part>> parts;
    for (size_t k = 0; k + 1 < ys.size(); ++k) parts.push_back(piece(k));
    const std::vector<Part> done = co_await d.all(std::move(parts));
    for (const Part& p : done) add(p);
  }
  co_return s;
}

// The inner integrals at a rule's nodes in x, the outer integral's integrand: every node's
// integral (of a rule, or of a piece's two halves) refined together.
struct InnerIntegrals {
  Density& density;
  const Nested& spec;

  template <size_t Rules>
  Task<std::array<Rule, Rules>> rules(std::array<double, Rules + 1> ends) const {
    std::vector<Task<Sample>> inner;
    inner.reserve(kNodes * Rules);
    for (size_t k = 0; k < Rules; ++k)
      for (double x : kronrodNodes(ends[k], ends[k + 1]))
        inner.push_back(innerIntegral(density, spec, x));
    const std::vector<Sample> s = co_await density.all(std::move(inner));
    co_return rulesFrom<Rules>(ends, [&](size_t i) { return s[i]; });
  }
  Task<std::array<Rule, 1>> rule(double a, double b) const { return rules<1>({a, b}); }
  Task<std::array<Rule, 2>> halves(double a, double m, double b) const {
    return rules<2>({a, m, b});
  }
};

Task<CellIntegral> nested(Density& d, Nested spec) {
  std::vector<double> xCuts;
  for (double b : spec.xBreaks)
    if (b > spec.x0 && b < spec.x1) xCuts.push_back(b);
  for (const Point2d& p : spec.peaks)
    addGradedCuts(p.x(), spec.x1 - spec.x0, spec.x0, spec.x1, xCuts);
  const std::vector<double> xs = pieces(spec.x0, spec.x1, std::move(xCuts));
  QuadratureOptions outer = spec.options;
  outer.relTolerance = spec.options.outerRelTolerance;
  const InnerIntegrals inner{d, spec};
  std::vector<Task<Part>> parts;
  for (size_t k = 0; k + 1 < xs.size(); ++k)
    parts.push_back(
        adaptive(d, inner, xs[k], xs[k + 1], outer,
                 spec.options.cellAbsTolerance * (xs[k + 1] - xs[k]) / (spec.x1 - spec.x0)));
  const std::vector<Part> done = co_await d.all(std::move(parts));
  CellIntegral result;
  for (const Part& p : done) {
    result.value += p.value;
    result.error += p.errors.rule + p.errors.carried;
  }
  co_return result;
}

Task<std::vector<CellIntegral>> gridIntegrals(Density& f, const Domain& domain,
                                              QuadratureOptions options,
                                              const DensityFeatures& features) {
  std::vector<Task<CellIntegral>> cells;
  cells.reserve(domain.cells());
  for (int c = 0; c < domain.cells(); ++c)
    cells.push_back(cellIntegral(f, features, domain, c, options));
  co_return co_await f.all(std::move(cells), true);
}

}  // namespace

double integrate2D(const DensityFn& f, double x0, double x1, double y0, double y1,
                   const QuadratureOptions& options, double* error) {
  Density d(f);
  const CellIntegral r = d.run(nested(d, {{}, {}, {}, nullptr, x0, x1, y0, y1, options, nullptr}));
  if (error) *error = r.error;
  return r.value;
}

namespace {

// ∫∫ f over a rectangle, as integrateRectangle; its rules along y kept in `memo` where given.
Task<CellIntegral> rectangle(Density& f, const DensityFeatures& features, const Domain& d,
                             CellBounds b, QuadratureOptions options, RuleMemo* memo) {
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
  // Named, not a temporary of the co_await expression: GCC 12 destroys such a temporary twice.
  Nested spec{features.breaksY,
              features.breaksX,
              std::move(near),
              &d,
              b.x0,
              b.x1,
              b.y0,
              b.y1,
              options,
              memo};
  const CellIntegral r = co_await nested(f, std::move(spec));
  co_return r;
}

}  // namespace

Task<CellIntegral> rectangleIntegral(Density& f, const DensityFeatures& features, const Domain& d,
                                     CellBounds b, QuadratureOptions options) {
  const CellIntegral r = co_await rectangle(f, features, d, b, options, nullptr);
  co_return r;
}

Task<CellIntegral> cellIntegral(Density& f, const DensityFeatures& features, const Domain& d,
                                int cell, QuadratureOptions options) {
  const CellBounds bounds = d.cell(cell);
  RuleMemo memo;
  // A pilot estimate (one Kronrod rule per piece) sets the cell's share of the grid's
  // absolute error budget as a relative tolerance.
  QuadratureOptions pilot = options;
  pilot.maxDepth = 0;
  const double estimate =
      std::fabs((co_await rectangle(f, features, d, bounds, pilot, &memo)).value);
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
  const CellIntegral coarse = co_await rectangle(f, features, d, bounds, o, &memo);
  // A large cell (relTolerance of its value above its share) that met relTolerance is as
  // accurate as a density evaluated in single precision allows: a second level would only
  // refine rounding steps (it took over half the rules of a rough dielectric's grid).
  if (options.verifyDepth == 0 || !(coarse.error > std::max(share, o.cellAbsTolerance)))
    co_return coarse;
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
  const CellIntegral r = co_await rectangle(f, features, d, bounds, fine, &memo);
  co_return CellIntegral{r.value, std::min(r.error, std::fabs(r.value - coarse.value))};
}

CellIntegral integrateRectangle(const DensityFn& f, const DensityFeatures& features,
                                const Domain& domain, const CellBounds& rectangle,
                                const QuadratureOptions& options) {
  Density d(f);
  return d.run(rectangleIntegral(d, features, domain, rectangle, options));
}

CellIntegral integrateCell(const DensityFn& f, const DensityFeatures& features,
                           const Domain& domain, int cell, const QuadratureOptions& options) {
  Density d(f);
  return d.run(cellIntegral(d, features, domain, cell, options));
}

std::vector<CellIntegral> integrateGrid(const DensityFn& f, const Domain& domain,
                                        const QuadratureOptions& options,
                                        const DensityFeatures& features) {
  Density d(f);
  return d.run(gridIntegrals(d, domain, options, features));
}

std::vector<CellIntegral> integrateGrid(const DensityBatchFn& f, const Domain& domain,
                                        const QuadratureOptions& options,
                                        const DensityFeatures& features) {
  Density d(f);
  return d.run(gridIntegrals(d, domain, options, features));
}

}  // namespace verity::chi2
