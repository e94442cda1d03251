#include <verity/chi2/quadrature.h>

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <bit>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <iterator>
#include <limits>
#include <tuple>
#include <type_traits>
#include <unordered_map>

#include "quadrature_tasks.h"

namespace verity::chi2 {

namespace {

using Kronrod = boost::math::quadrature::gauss_kronrod<double, 15>;
using Gauss = boost::math::quadrature::gauss<double, 7>;
constexpr size_t kNodes = kRuleNodes;

// A value of the integrand with the error it carries: the inner integral of a nested
// quadrature, and that integral's own error estimate.
struct Sample {
  double value = 0, error = 0;
  double noise = 0;  // the part of `error` that round-off noise makes (Errors)
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
  double carriedNoise = 0;  // the part of `carried` that is its integrand's noise
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
  double cn = centre.noise * wk[0];
  for (unsigned i = 2; i < x.size(); i += 2, n += 2) {
    const Sample p = at(n), m = at(n + 1);
    k += (p.value + m.value) * wk[i];
    g += (p.value + m.value) * wg[i / 2];
    c += (p.error + m.error) * wk[i];
    cn += (p.noise + m.noise) * wk[i];
  }
  for (unsigned i = 1; i < x.size(); i += 2, n += 2) {
    const Sample p = at(n), m = at(n + 1);
    k += (p.value + m.value) * wk[i];
    c += (p.error + m.error) * wk[i];
    cn += (p.noise + m.noise) * wk[i];
  }
  Rule r;
  r.value = scale * k;
  r.error = std::max(std::fabs(k - g), std::fabs(k * std::numeric_limits<double>::epsilon() * 2));
  r.carried = scale * c;
  r.carriedNoise = scale * cn;
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

// A rule that keeps its integrand's values at its nodes, so that a distribution can be
// inverted inside its piece (the partition's tabulations, quadrature_tasks.h).
struct NodeRule : Rule {
  Nodes at{};
  using Kept = QuadratureLeaf;
  QuadratureLeaf keep(double a, double b) && { return {a, b, value, at}; }
};
// An outer rule of a tabulation: its nodes' values are inner integrals, each kept with its
// leaves (the profile along y at that node).
struct ProfileRule : Rule {
  Nodes at{};
  std::array<Profile, kNodes> profiles;
  using Kept = OuterLeaf;
  OuterLeaf keep(double a, double b) && { return {{a, b, value, at}, std::move(profiles)}; }
};

// Where a 1D integral's error lies: its own rule's estimates and the error its integrand
// carried (both in the integral's units), which add; and the round-off noise of its own
// pieces accepted as such (Part::noise), squared: the errors of different pieces along one
// line are independent draws of the staircase's rounding, of either sign, so they add in
// quadrature (`total`). The errors that inner integrals carry into the outer one are added
// as they are: at nearby x the steps along y lie alike (a density of separate factors in x
// and y repeats them exactly), so their errors need not be independent.
struct Errors {
  double rule = 0, carried = 0, noise2 = 0;
  double carriedNoise = 0;  // the part of `carried` that is the integrand's noise

  double total() const { return rule + carried + std::sqrt(noise2); }
  // The part of total() that round-off noise makes, here or in the integrand.
  double noise() const { return carriedNoise + std::sqrt(noise2); }
};

// A piece's integral and where its error lies: what an adaptive integral returns, from its
// accepted pieces (leaf), a piece whose halves are round-off noise (noise), and two halves.
struct Part {
  double value = 0;
  Errors errors;

  static Part leaf(const Rule& r, double a, double b) {
    return {r.value, {r.error * (b - a) / 2, r.carried, 0, r.carriedNoise}};
  }
  static Part noise(const Rule& r0, const Rule& r1, double a, double b) {
    const double e = (r0.error + r1.error) * (b - a) / 4;
    return {r0.value + r1.value,
            {0, r0.carried + r1.carried, e * e, r0.carriedNoise + r1.carriedNoise}};
  }
  static Part sum(const Part& p, const Part& q) {
    return {p.value + q.value,
            {p.errors.rule + q.errors.rule, p.errors.carried + q.errors.carried,
             p.errors.noise2 + q.errors.noise2, p.errors.carriedNoise + q.errors.carriedNoise}};
  }
};

// The same with the accepted pieces themselves, in order: a tabulation's (R: NodeRule or
// ProfileRule).
template <class R>
struct Leaves {
  Part part;
  std::vector<typename R::Kept> kept;

  static Leaves leaf(R&& r, double a, double b) {
    Leaves l{Part::leaf(r, a, b), {}};
    l.kept.push_back(std::move(r).keep(a, b));
    return l;
  }
  static Leaves noise(R&& r0, R&& r1, double a, double b) {
    Leaves l{Part::noise(r0, r1, a, b), {}};
    const double m = 0.5 * (a + b);
    l.kept.push_back(std::move(r0).keep(a, m));
    l.kept.push_back(std::move(r1).keep(m, b));
    return l;
  }
  static Leaves sum(Leaves&& p, Leaves&& q) {
    p.part = Part::sum(p.part, q.part);
    std::move(q.kept.begin(), q.kept.end(), std::back_inserter(p.kept));
    return std::move(p);
  }
};
template <class R>
using ResultOf = std::conditional_t<std::is_same_v<R, Rule>, Part, Leaves<R>>;

// The rules a computation took along y, by their x and piece: a cell's pilot estimate, its
// coarse level and its verifying level start from the same pieces, whose densities are then
// evaluated once (half the points of a smooth lobe's grid). With `nodes`, the rules' values at
// their nodes too, for a tabulation to reuse the rules of the pilot that set its tolerances.
// Kept by one computation at a time; once frozen, read by any number at once.
class RuleMemo {
 public:
  explicit RuleMemo(bool nodes = false) : keepsNodes_(nodes) {}

  // The rule on [a, b] at x, and its nodes' values where kept (else null).
  std::pair<const Rule*, const Nodes*> find(double x, double a, double b) const {
    const auto it = rules_.find(key(x, a, b));
    if (it == rules_.end()) return {nullptr, nullptr};
    return {&it->second, keepsNodes_ ? &nodes_[it->second.index] : nullptr};
  }
  // `values`: the integrand at the rule's nodes.
  void keep(double x, double a, double b, const Rule& r, const double* values) {
    if (frozen_) return;
    const bool added = rules_.try_emplace(key(x, a, b), Kept{r, nodes_.size()}).second;
    if (added && keepsNodes_) std::copy_n(values, kNodes, nodes_.emplace_back().begin());
  }
  void freeze() { frozen_ = true; }

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
  struct Kept : Rule {
    size_t index = 0;  // of its nodes' values in nodes_
  };
  std::unordered_map<Key, Kept, Hash> rules_;
  std::vector<Nodes> nodes_;
  bool keepsNodes_ = false, frozen_ = false;
};

// The density along y at one x, the inner integrals' integrand. Its rules are awaiters, not
// computations: the nodes of a rule, or of a piece's two halves, in one request, unless the
// memo has them all.
template <class R>
struct AlongYOf {
  using Result = ResultOf<R>;
  Density& density;
  double x;
  RuleMemo* memo = nullptr;

  template <size_t Rules>
  struct NodeValues {
    const AlongYOf& along;
    std::array<double, Rules + 1> ends;
    std::array<R, Rules> rules;
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
        for (size_t k = 0; k < Rules && remembered; ++k) {
          const auto [rule, nodes] = along.memo->find(along.x, ends[k], ends[k + 1]);
          if constexpr (std::is_same_v<R, Rule>) {
            remembered = rule != nullptr;
            if (rule) rules[k] = *rule;
          } else {
            remembered = nodes != nullptr;
            if (nodes) {
              static_cast<Rule&>(rules[k]) = *rule;
              rules[k].at = *nodes;
            }
          }
        }
        if (remembered) return true;
      }
      return request().await_ready();
    }
    void await_suspend(std::coroutine_handle<> waiting) {
      along.density.wait(points.data(), values.data(), points.size(), waiting);
    }
    std::array<R, Rules> await_resume() {
      if (remembered) return rules;
      const auto plain = rulesFrom<Rules>(ends, [&](size_t i) { return Sample{values[i], 0}; });
      for (size_t k = 0; k < Rules; ++k) {
        const double* at = values.data() + k * kNodes;
        if (along.memo) along.memo->keep(along.x, ends[k], ends[k + 1], plain[k], at);
        static_cast<Rule&>(rules[k]) = plain[k];
        if constexpr (!std::is_same_v<R, Rule>) std::copy_n(at, kNodes, rules[k].at.begin());
      }
      return rules;
    }
  };
  // co_await rule(a, b): a Rule; co_await halves(a, m, b): both halves' rules.
  NodeValues<1> rule(double a, double b) const { return {*this, {a, b}}; }
  NodeValues<2> halves(double a, double m, double b) const { return {*this, {a, m, b}}; }
  // The larger of the density at y = a and y = b (kZeroHalvings below).
  Task<double> atEnds(double a, double b) const {
    const std::array<Point2d, 2> points{Point2d(x, a), Point2d(x, b)};
    std::array<double, 2> values{};
    co_await density.at(points.data(), values.data(), points.size());
    co_return std::max(values[0], values[1]);
  }
};

using AlongY = AlongYOf<Rule>;

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

// Whether a piece is accepted as its rule gives it: within its share of the tolerance, or at
// the greatest depth.
bool accepted(const Rule& r, double a, double b, double tolerancePerWidth, unsigned depth) {
  return depth == 0 || r.error <= tolerancePerWidth * (b - a);
}

// A rule on [a, b] that found next to nothing, within the piece's share of a tolerance that
// has an absolute scale: an exact 0, a tail, or a lobe that the nodes all missed, but for its
// tail. Whether it missed one, its integrand at the ends tells (atEnds, kZeroHalvings).
bool mayHideMass(const Rule& r, double a, double b, double tolerancePerWidth) {
  return tolerancePerWidth > 0 && std::fabs(r.value) + r.carried <= tolerancePerWidth * (b - a);
}

// How many times a piece whose rule found next to nothing (mayHideMass) is halved towards an
// end where its integrand is larger than the piece's share of the tolerance per width (atEnds:
// what would be missed if the integrand held that value over the whole piece; an integral
// without an absolute tolerance has no such scale, and is not halved so), on top of the depth.
// The rule's nodes stop 0.43% of a piece short of its ends, so a lobe narrower than that
// against a cell's edge (an anisotropic lobe 10⁻⁴ wide beside a strip holding 1.57 rad of
// azimuth, whose density a peer's BSDF cut to exactly 0 below 10⁻²⁰) was read from its tail
// alone, 10⁻¹³ of a mass of 4·10⁻⁴: samples fell in cells that expected none, and a correct
// BSDF FAILED. Twenty halvings bring a lobe 10⁻⁷ of the piece wide (the resolution of single
// precision) within reach of the nodes; an end where the integrand is itself negligible (Phong
// 10⁴ beyond its lobe) is left as it was.
constexpr unsigned kZeroHalvings = 20;
// Only the integrals whose values the checks use: a tabulation that cuts cells (partition.h)
// need not see such a lobe, which the cells' integrals then find (its halvings, each a profile
// along y, cost the partition of a Phong 10⁴ lobe 100 times its evaluations).
template <class Result>
constexpr bool kHalvesTowardsMass = std::is_same_v<Result, Part>;

// Bisection with the 15-point Gauss–Kronrod rule on each piece (the comment above), of a piece
// its rule did not settle; the halves of a piece, and their own halves, are refined together.
// A half accepted as it is costs no computation of its own.
template <class Integrand>
Task<typename Integrand::Result> bisect(Density& d, const Integrand& f, double a, double b,
                                        Rule whole, double tolerancePerWidth, unsigned depth,
                                        bool parentStalled = false, unsigned zeroHalvings = 0) {
  using Result = typename Integrand::Result;
  const double m = 0.5 * (a + b);
  auto halves = co_await f.halves(a, m, b);
  const Rule r0 = halves[0], r1 = halves[1];
  const double e0 = r0.error, e1 = r1.error;
  // Round-off detection (as in QUADPACK's QAG, Piessens et al. 1983): bisection shrinks the
  // error of a smooth piece many times and that of a jump by half, but leaves the
  // staircase of a density evaluated in single precision as large as it was. Refining
  // noise buys nothing; accept the halves. A jump, a kink or a lobe that the halves find
  // and the whole missed can raise the error too, but it sits in one half (the halves'
  // errors are unequal) or moves the estimate by more than its error. Noise's estimates
  // are draws of |K15 − G7|, so their ratio falls below 1/4 by chance for 31% of noisy
  // bisections (below 1/20 for 6%): with those whose sum fell below 0.8 by chance, a noisy
  // piece went on with probability 0.46 and left two, every staircase to the depth limit.
  // So a bisection that stalled (did not shrink, moved the estimate by no more than its
  // error) under a parent that stalled too is noise unless one half holds at most 1/20 of
  // the other's error, as a jump's smooth half does. Measured: a Phong 10⁴ lobe in float
  // 42.5M → 24.3M evaluations (chi2_staircase_bench); the narrowest lobe of the sweep
  // (Beckmann α = 10⁻⁴, a rough dielectric at 45°), which one bisection at 1/10 took for
  // noise (∫pdf 1.000120 against 1.000038), is unchanged (1.000044).
  const bool stalled = e0 + e1 > 0.8 * whole.error &&
                       std::fabs(r0.value + r1.value - whole.value) <= 2 * whole.error;
  const double ratio = std::min(e0, e1) / std::max(e0, e1);
  const bool noise = stalled && (ratio > 0.25 || (parentStalled && ratio > 0.05));
  if (noise) co_return Result::noise(std::move(halves[0]), std::move(halves[1]), a, b);
  const bool accepted0 = accepted(r0, a, m, tolerancePerWidth, depth - 1),
             accepted1 = accepted(r1, m, b, tolerancePerWidth, depth - 1);
  // A half that found next to nothing, with mass at an end, is halved again, its depth kept
  // (kZeroHalvings).
  bool towards0 = false, towards1 = false;
  if constexpr (kHalvesTowardsMass<Result>)
    if (zeroHalvings < kZeroHalvings) {
      towards0 = accepted0 && mayHideMass(r0, a, m, tolerancePerWidth) &&
                 co_await f.atEnds(a, m) > tolerancePerWidth;
      towards1 = accepted1 && mayHideMass(r1, m, b, tolerancePerWidth) &&
                 co_await f.atEnds(m, b) > tolerancePerWidth;
    }
  const bool done0 = accepted0 && !towards0, done1 = accepted1 && !towards1;
  const unsigned depth0 = towards0 ? depth : depth - 1, depth1 = towards1 ? depth : depth - 1;
  const unsigned halvings0 = zeroHalvings + towards0, halvings1 = zeroHalvings + towards1;
  std::array<Result, 2> p;
  if (done0) p[0] = Result::leaf(std::move(halves[0]), a, m);
  if (done1) p[1] = Result::leaf(std::move(halves[1]), m, b);
  if (!done0 && !done1)
    p = co_await d.both(bisect(d, f, a, m, r0, tolerancePerWidth, depth0, stalled, halvings0),
                        bisect(d, f, m, b, r1, tolerancePerWidth, depth1, stalled, halvings1));
  else if (!done0)
    p[0] = co_await bisect(d, f, a, m, r0, tolerancePerWidth, depth0, stalled, halvings0);
  else if (!done1)
    p[1] = co_await bisect(d, f, m, b, r1, tolerancePerWidth, depth1, stalled, halvings1);
  co_return Result::sum(std::move(p[0]), std::move(p[1]));
}

// The adaptive integral of an integrand of Samples, to max(relTolerance·|∫f|, absTolerance).
template <class Integrand>
Task<typename Integrand::Result> adaptive(Density& d, const Integrand& f, double a, double b,
                                          QuadratureOptions options, double absTolerance) {
  using Result = typename Integrand::Result;
  if (!(b > a)) co_return Result{};
  auto first = co_await f.rule(a, b);
  const Rule whole = first[0];
  const double tolerance = std::max(options.relTolerance * std::fabs(whole.value), absTolerance);
  const double perWidth = tolerance / (b - a);
  if (!accepted(whole, a, b, perWidth, options.maxDepth))
    co_return co_await bisect(d, f, a, b, whole, perWidth, options.maxDepth);
  // Nodes that found next to nothing prove nothing where the integrand is more than that at an
  // end: halve towards it, keeping the whole depth for what the halves find.
  if constexpr (kHalvesTowardsMass<Result>)
    if (mayHideMass(whole, a, b, perWidth) && co_await f.atEnds(a, b) > perWidth)
      co_return co_await bisect(d, f, a, b, whole, perWidth, options.maxDepth + 1, false, 1);
  co_return Result::leaf(std::move(first[0]), a, b);
}

}  // namespace

double integrate1D(const std::function<double(double)>& f, double a, double b,
                   const QuadratureOptions& options, double* error, double absTolerance) {
  const DensityFn alongY = [&](double, double y) { return f(y); };
  Density d(alongY);
  const AlongY integrand{d, 0};
  const Part p = d.run(adaptive(d, integrand, a, b, options, absTolerance));
  if (error) *error = p.errors.total();
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
  BreakpointFn crossings;  // where the jumps of `breaks` pass a given height
};

// The pieces of the inner range at x, in order: the support's extent in y split at the
// density's jumps and graded towards the peaks; none where the support is empty there.
std::vector<double> innerPieces(const Nested& spec, double x) {
  double lo = spec.y0, hi = spec.y1;
  if (spec.domain) std::tie(lo, hi) = spec.domain->clipY(x, spec.y0, spec.y1);
  if (!(hi > lo)) return {};
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
  return pieces(lo, hi, std::move(cuts));
}

// The cell's absolute budget, spread over y, for the piece [ys[k], ys[k + 1]]; an inner error
// enters the cell times its width.
double pieceTolerance(const Nested& spec, const std::vector<double>& ys, size_t k) {
  return spec.options.cellAbsTolerance * (ys[k + 1] - ys[k]) /
         ((spec.y1 - spec.y0) * (spec.x1 - spec.x0));
}

// The inner integral at x with its error estimate, which the outer rule integrates over x
// with its own weights (the nested rule's error is at most the outer rule's error plus
// ∫ |inner error| dx). An unweighted mean over the calls would count a call on a piece
// graded 10⁻⁷ of a cell wide, next to a peak or a jump, as much as one on a whole cell.
Task<Sample> innerIntegral(Density& d, const Nested& spec, double x) {
  const std::vector<double> ys = innerPieces(spec, x);
  if (ys.empty()) co_return Sample{};
  const AlongY along{d, x, spec.memo};
  auto piece = [&](size_t k) {
    return adaptive(d, along, ys[k], ys[k + 1], spec.options, pieceTolerance(spec, ys, k));
  };
  Sample s;
  auto add = [&](const Part& p) {
    s.value += p.value;
    s.error += p.errors.total();
    s.noise += p.errors.noise();
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
  using Result = Part;
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
  // The larger of the inner integrals at x = a and x = b.
  Task<double> atEnds(double a, double b) const {
    const auto [at, bt] =
        co_await density.both(innerIntegral(density, spec, a), innerIntegral(density, spec, b));
    co_return std::max(at.value, bt.value);
  }
};

// The outer range's pieces, in order: split at the density's jumps in x and graded towards
// the peaks.
std::vector<double> outerPieces(const Nested& spec) {
  std::vector<double> xCuts;
  for (double b : spec.xBreaks)
    if (b > spec.x0 && b < spec.x1) xCuts.push_back(b);
  // Where a jump enters or leaves through the lower or upper edge, the inner integral starts
  // or stops there: a jump that dips just into the rectangle leaves it a sliver of density
  // that the outer rule's nodes may all miss.
  if (spec.crossings)
    for (double y : {spec.y0, spec.y1})
      for (double b : spec.crossings(y))
        if (b > spec.x0 && b < spec.x1) xCuts.push_back(b);
  for (const Point2d& p : spec.peaks)
    addGradedCuts(p.x(), spec.x1 - spec.x0, spec.x0, spec.x1, xCuts);
  return pieces(spec.x0, spec.x1, std::move(xCuts));
}

Task<CellIntegral> nested(Density& d, Nested spec) {
  const std::vector<double> xs = outerPieces(spec);
  QuadratureOptions outer = spec.options;
  outer.relTolerance = spec.options.outerRelTolerance;
  const InnerIntegrals inner{d, spec};
  std::vector<Task<Part>> parts;
  for (size_t k = 0; k + 1 < xs.size(); ++k)
    parts.push_back(
        adaptive(d, inner, xs[k], xs[k + 1], outer,
                 spec.options.cellAbsTolerance * (xs[k + 1] - xs[k]) / (spec.x1 - spec.x0)));
  const std::vector<Part> done = co_await d.all(std::move(parts));
  Part all;
  for (const Part& p : done) all = Part::sum(all, p);
  co_return CellIntegral{all.value, all.errors.total(), all.errors.noise()};
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

// The nested integral over a rectangle, as integrateRectangle computes it; its rules along y
// kept in `memo` where given.
Nested specFor(const DensityFeatures& features, const Domain& d, const CellBounds& b,
               const QuadratureOptions& options, RuleMemo* memo) {
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
    // φ means nothing at a pole: a peak on it is graded there (innerPieces). One merely near
    // it is a peak like any other: a narrow lobe 20° from the pole lies within the top row of
    // 32 cells in cos θ, and was once left to the pole's grading, which never reached it (a
    // rough dielectric of α 10⁻⁴ at 30° FAILED, 96% of its samples where the quadrature found
    // no density).
    if (!(sphere && 1 - std::fabs(p.y()) < 1e-12) && p.x() > b.x0 - marginX &&
        p.x() < b.x1 + marginX && p.y() > b.y0 - marginY && p.y() < b.y1 + marginY)
      near.push_back(p);
  return {features.breaksY,
          features.breaksX,
          std::move(near),
          &d,
          b.x0,
          b.x1,
          b.y0,
          b.y1,
          options,
          memo,
          features.crossingsX};
}

// ∫∫ f over a rectangle, as integrateRectangle; its rules along y kept in `memo` where given.
Task<CellIntegral> rectangle(Density& f, const DensityFeatures& features, const Domain& d,
                             CellBounds b, QuadratureOptions options, RuleMemo* memo) {
  // Named, not a temporary of the co_await expression: GCC 12 destroys such a temporary twice.
  Nested spec = specFor(features, d, b, options, memo);
  const CellIntegral r = co_await nested(f, std::move(spec));
  co_return r;
}

// Tabulations (quadrature_tasks.h): the same nested integral, keeping its leaves.

// Pieces narrower than this fraction of their range are not split for their mass: the
// densities are evaluated in single precision, whose steps (~10⁻⁷ relative) are coarser.
constexpr double kMinWidth = 1e-9;

// The profile along y at x: the inner integral, as innerIntegral computes it, with its leaves.
Task<Profile> profileAt(Density& d, const Nested& spec, double x) {
  Profile p;
  p.x = x;
  const std::vector<double> ys = innerPieces(spec, x);
  if (ys.empty()) co_return p;
  const AlongYOf<NodeRule> along{d, x, spec.memo};
  std::vector<Task<Leaves<NodeRule>>> parts;
  parts.reserve(ys.size() - 1);
  for (size_t k = 0; k + 1 < ys.size(); ++k)
    parts.push_back(
        adaptive(d, along, ys[k], ys[k + 1], spec.options, pieceTolerance(spec, ys, k)));
  std::vector<Leaves<NodeRule>> done = co_await d.all(std::move(parts));
  for (Leaves<NodeRule>& l : done) {
    p.value += l.part.value;
    p.error += l.part.errors.total();
    std::move(l.kept.begin(), l.kept.end(), std::back_inserter(p.leaves));
  }
  co_return p;
}

// The profiles at a rule's nodes in x, a tabulation's outer integrand (as InnerIntegrals).
struct ProfileIntegrals {
  using Result = Leaves<ProfileRule>;
  Density& density;
  const Nested& spec;

  template <size_t Rules>
  Task<std::array<ProfileRule, Rules>> rules(std::array<double, Rules + 1> ends) const {
    std::vector<Task<Profile>> inner;
    inner.reserve(kNodes * Rules);
    for (size_t k = 0; k < Rules; ++k)
      for (double x : kronrodNodes(ends[k], ends[k + 1]))
        inner.push_back(profileAt(density, spec, x));
    std::vector<Profile> s = co_await density.all(std::move(inner), true);
    const auto plain = rulesFrom<Rules>(ends, [&](size_t i) {
      return Sample{s[i].value, s[i].error};
    });
    std::array<ProfileRule, Rules> r;
    for (size_t k = 0; k < Rules; ++k) {
      static_cast<Rule&>(r[k]) = plain[k];
      for (size_t i = 0; i < kNodes; ++i) {
        r[k].at[i] = s[k * kNodes + i].value;
        r[k].profiles[i] = std::move(s[k * kNodes + i]);
      }
    }
    co_return r;
  }
  Task<std::array<ProfileRule, 1>> rule(double a, double b) const { return rules<1>({a, b}); }
  Task<std::array<ProfileRule, 2>> halves(double a, double m, double b) const {
    return rules<2>({a, m, b});
  }
};

const QuadratureLeaf& ends(const QuadratureLeaf& l) {
  return l;
}
const QuadratureLeaf& ends(const OuterLeaf& l) {
  return l.leaf;
}

// A leaf's two halves, each with its own rule (Kronrod nodes do not nest).
template <class Integrand, class Kept>
Task<std::array<Kept, 2>> halvesOf(const Integrand& f, Kept leaf) {
  const double a = ends(leaf).a, b = ends(leaf).b, m = 0.5 * (a + b);
  auto h = co_await f.halves(a, m, b);
  co_return std::array<Kept, 2>{std::move(h[0]).keep(a, m), std::move(h[1]).keep(m, b)};
}

// The leaves bisected, level by level, until each holds at most `share` of their total (or
// is minWidth wide). The total is taken afresh at each level, so that a lobe that the
// adaptive rule underestimated does not make every piece of it "large"; at most 1/share
// leaves exceed it, so a level costs at most 2/share rules, and there are at most
// kSplitLevels: a bounded cost whatever the density does (a staircase of single-precision
// steps included). Where the levels run out, the steps of a leaf hold more than their share
// (partition.h says what that costs).
constexpr int kSplitLevels = 12;
template <class Integrand, class Kept>
Task<std::vector<Kept>> splitAll(Density& d, const Integrand& f, std::vector<Kept> leaves,
                                 double share, double minWidth) {
  for (int level = 0; level < kSplitLevels; ++level) {
    double total = 0;
    for (const Kept& l : leaves) total += ends(l).value;
    const double most = share * total;
    std::vector<Task<std::array<Kept, 2>>> halves;
    for (const Kept& l : leaves)
      if (ends(l).value > most && ends(l).b - ends(l).a > minWidth)
        halves.push_back(halvesOf(f, l));
    if (halves.empty()) break;
    std::vector<std::array<Kept, 2>> done = co_await d.all(std::move(halves));
    std::vector<Kept> next;
    size_t k = 0;
    for (Kept& l : leaves)
      if (ends(l).value > most && ends(l).b - ends(l).a > minWidth) {
        next.push_back(std::move(done[k][0]));
        next.push_back(std::move(done[k++][1]));
      } else {
        next.push_back(std::move(l));
      }
    leaves = std::move(next);
  }
  co_return leaves;
}

Task<std::vector<OuterLeaf>> tabulate(Density& d, Nested spec, double xShare, double yShare) {
  const std::vector<double> xs = outerPieces(spec);
  QuadratureOptions outer = spec.options;
  outer.relTolerance = spec.options.outerRelTolerance;
  const ProfileIntegrals inner{d, spec};
  std::vector<Task<Leaves<ProfileRule>>> parts;
  parts.reserve(xs.size() - 1);
  for (size_t k = 0; k + 1 < xs.size(); ++k)
    parts.push_back(
        adaptive(d, inner, xs[k], xs[k + 1], outer,
                 spec.options.cellAbsTolerance * (xs[k + 1] - xs[k]) / (spec.x1 - spec.x0)));
  std::vector<Leaves<ProfileRule>> done = co_await d.all(std::move(parts), true);
  std::vector<OuterLeaf> leaves;
  for (Leaves<ProfileRule>& l : done) {
    std::move(l.kept.begin(), l.kept.end(), std::back_inserter(leaves));
  }
  if (xShare > 0)
    leaves =
        co_await splitAll(d, inner, std::move(leaves), xShare, kMinWidth * (spec.x1 - spec.x0));
  if (yShare > 0) {
    std::vector<AlongYOf<NodeRule>> along;
    along.reserve(leaves.size() * kNodes);
    std::vector<Task<std::vector<QuadratureLeaf>>> profiles;
    profiles.reserve(leaves.size() * kNodes);
    for (OuterLeaf& o : leaves)
      for (Profile& p : o.profiles) {
        along.push_back({d, p.x});
        profiles.push_back(splitAll(d, along.back(), std::move(p.leaves), yShare,
                                    kMinWidth * (spec.y1 - spec.y0)));
      }
    std::vector<std::vector<QuadratureLeaf>> split = co_await d.all(std::move(profiles), true);
    size_t k = 0;
    for (OuterLeaf& o : leaves)
      for (Profile& p : o.profiles) p.leaves = std::move(split[k++]);
  }
  co_return leaves;
}

// C(j, i) = ∫ from −1 to −1 + 2(j + 1)/kLeafSteps of ℓ_i, the Lagrange polynomial of the
// rule's node i (kronrodNodes(−1, 1)): the integral of the polynomial interpolating a leaf's
// values up to each step. Through the Legendre basis, well conditioned on these nodes:
// ℓ = V⁻¹ P with V(i, m) = P_m(t_i), and ∫_{−1}^{s} P_m = (P_{m+1}(s) − P_{m−1}(s))/(2m + 1).
const Eigen::Matrix<double, kLeafSteps, kNodes>& cumulativeWeights() {
  static const Eigen::Matrix<double, kLeafSteps, kNodes> c = [] {
    auto legendre = [](double s, size_t count) {
      std::vector<double> p{1.0, s};
      for (size_t m = 1; m + 1 < count; ++m)
        p.push_back(((2 * m + 1) * s * p[m] - m * p[m - 1]) / (m + 1));
      return p;
    };
    const Nodes t = kronrodNodes(-1, 1);
    Eigen::Matrix<double, kNodes, kNodes> v;
    for (size_t i = 0; i < kNodes; ++i) {
      const std::vector<double> p = legendre(t[i], kNodes);
      for (size_t m = 0; m < kNodes; ++m) v(i, m) = p[m];
    }
    Eigen::Matrix<double, kLeafSteps, kNodes> q;
    for (int j = 0; j < kLeafSteps; ++j) {
      const double s = -1 + 2.0 * (j + 1) / kLeafSteps;
      const std::vector<double> p = legendre(s, kNodes + 1);
      q(j, 0) = s + 1;
      for (size_t m = 1; m < kNodes; ++m) q(j, m) = (p[m + 1] - p[m - 1]) / (2 * m + 1);
    }
    return Eigen::Matrix<double, kLeafSteps, kNodes>(q * v.inverse());
  }();
  return c;
}

}  // namespace

Task<std::vector<OuterLeaf>> tabulateRectangle(Density& f, const DensityFeatures& features,
                                               const Domain& d, CellBounds b,
                                               QuadratureOptions options, double xShare,
                                               double yShare) {
  Nested spec = specFor(features, d, b, options, nullptr);
  std::vector<OuterLeaf> r = co_await tabulate(f, std::move(spec), xShare, yShare);
  co_return r;
}

Task<std::vector<OuterLeaf>> tabulateRectangleToItsMass(
    Density& f, const DensityFeatures& features, const Domain& d, CellBounds b,
    std::function<QuadratureOptions(double mass)> options, double xShare, double yShare) {
  RuleMemo memo(true);
  QuadratureOptions pilot = options(0);
  pilot.maxDepth = 0;
  const CellIntegral estimate = co_await rectangle(f, features, d, b, pilot, &memo);
  memo.freeze();
  Nested spec = specFor(features, d, b, options(estimate.value), &memo);
  std::vector<OuterLeaf> r = co_await tabulate(f, std::move(spec), xShare, yShare);
  co_return r;
}

Task<Profile> profileAlongY(Density& f, const DensityFeatures& features, const Domain& d,
                            CellBounds b, QuadratureOptions options, double x) {
  Nested spec = specFor(features, d, b, options, nullptr);
  Profile p = co_await profileAt(f, spec, x);
  co_return p;
}

std::array<double, kRuleNodes> ruleWeights(double a, double b) {
  const double scale = (b - a) / 2;
  const auto& wk = Kronrod::weights();
  std::array<double, kRuleNodes> w;
  size_t n = 0;
  w[n++] = wk[0] * scale;
  for (unsigned i = 2; i < wk.size(); i += 2, n += 2) w[n] = w[n + 1] = wk[i] * scale;
  for (unsigned i = 1; i < wk.size(); i += 2, n += 2) w[n] = w[n + 1] = wk[i] * scale;
  return w;
}

std::vector<double> leafCumulative(const QuadratureLeaf& leaf, int steps) {
  const auto& c = cumulativeWeights();
  const double scale = (leaf.b - leaf.a) / 2;
  std::vector<double> cum(steps);
  for (int j = 0; j < steps; ++j) {
    const int row = (j + 1) * (kLeafSteps / steps) - 1;
    double s = 0;
    for (size_t i = 0; i < kNodes; ++i) s += c(row, i) * leaf.at[i];
    cum[j] = scale * s;
  }
  return cum;
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
  // Nor would it reduce the noise (CellIntegral::noise), whose pieces it would accept again:
  // only the rest of the estimate is worth a second level.
  if (options.verifyDepth == 0 ||
      !(coarse.error - coarse.noise > std::max(share, o.cellAbsTolerance)))
    co_return coarse;
  // The cell missed its tolerance. Either a feature is not yet resolved, or the
  // density is a staircase of single-precision rounding steps (grazing Beckmann and GGX,
  // tiny roughness, the cancellation in ωi + ωo near −ωi): then every piece's |K15 − G7|
  // stays at the steps' size however far it is bisected, and the sum counts their errors,
  // of either sign, in absolute value (10⁻⁴ and more of a cell whose value moves by 10⁻⁷
  // when refined). So compare two refinement levels: integrate again with every piece
  // bisected verifyDepth more times and tolerances ten times tighter, and keep the finer
  // value. Where the refinement converges (the finer error at most half the coarser), the
  // finer value's error is at most the change |fine − coarse| plus its noise (the pieces
  // accepted as round-off noise are the same in both levels, so the change does not see
  // their errors: CellIntegral::noise); its own Gauss–Kronrod estimate is the other bound,
  // and the smaller of the two is reported. This is a
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
  const double change = std::fabs(r.value - coarse.value);
  if (change + r.noise < r.error) co_return CellIntegral{r.value, change + r.noise, r.noise};
  co_return r;
}

CellIntegral integrateRectangle(const DensityFn& f, const DensityFeatures& features,
                                const Domain& domain, const CellBounds& bounds,
                                const QuadratureOptions& options) {
  Density d(f);
  return d.run(rectangle(d, features, domain, bounds, options, nullptr));
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
