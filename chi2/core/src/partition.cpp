#include <fmt/format.h>
#include <verity/chi2/partition.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>

#include "quadrature_tasks.h"

namespace verity::chi2 {

std::string cellLayoutName(CellLayout layout) {
  return layout == CellLayout::Grid ? "grid" : "equal";
}

CellLayout parseCellLayout(const std::string& name, const std::string& option) {
  if (name == "equal") return CellLayout::EqualProbability;
  if (name == "grid") return CellLayout::Grid;
  throw std::invalid_argument(
      fmt::format("{}: '{}' is no cell layout: 'equal' (cells of equal probability under the "
                  "claimed pdf) or 'grid' (the uniform grid)",
                  option, name));
}

namespace {

// A piece [a, b] of a range, the mass the density holds over it, and whether the density is
// zero all over it (at every node of the rules that tabulated it).
struct Piece {
  double a = 0, b = 0, mass = 0;
  bool zero = false;
};

// The distribution is resolved into steps of about 1/(kSplit·n) of the mass to be cut into
// n: an edge placed by linear interpolation inside a step then errs by at most that much, and
// by far less where the density is smooth across it (second order in its width).
constexpr double kSplit = 4;

// What the inversion integrates, by the quadrature's own nested rule and error control
// (quadrature_tasks.h), keeping its leaves. The cells' probabilities are integrated afterwards
// to the test's tolerances (integrateGrid), so the edges need only be good to a small part of
// a cell's share: the inner integrals to 10⁻³ of their own value or of the mass being cut
// (the rectangle's, `mass`), the outer to 10⁻², as the pieces of the inversion that this
// replaces were; no second, verifying level.
QuadratureOptions tabulationOptions(QuadratureOptions o, double mass) {
  o.relTolerance = 1e-3;
  o.outerRelTolerance = 1e-2;
  o.verifyDepth = 0;
  o.cellAbsTolerance = std::isfinite(mass) ? 1e-3 * std::fabs(mass) : 0;
  return o;
}

// The steps a leaf's distribution is resolved into: a power of two, up to kLeafSteps, that
// leaves each about 1/(kSplit·n) of `total` at most. The leaves themselves are split by the
// tabulation until they hold at most kLeafSteps such steps (leafShare).
int stepsFor(double value, double total, int n) {
  int steps = 1;
  while (steps < kLeafSteps && value > steps * total / (kSplit * n)) steps *= 2;
  return steps;
}
double leafShare(int n) {
  return kLeafSteps / (kSplit * n);
}

// A piecewise linear cumulative distribution: its values cum[k] at knots at[k], increasing,
// and zero[k] where the density is zero all over [at[k], at[k + 1]].
struct Knots {
  std::vector<double> at, cum;
  std::vector<char> zero;

  void add(double x, double c, bool z) {
    at.push_back(x);
    cum.push_back(c);
    zero.push_back(z);
  }
  // The distribution at x: 0 before the first knot, the total after the last.
  double operator()(double x, size_t& k) const {
    if (at.empty() || x <= at.front()) return 0;
    if (x >= at.back()) return cum.back();
    while (at[k + 1] < x) ++k;
    return cum[k] + (cum[k + 1] - cum[k]) * (x - at[k]) / (at[k + 1] - at[k]);
  }
  // Whether the density is zero over the interval holding x. Outside the knots, beyond the
  // support at this node (the disk's, the triangle's), nothing is known: another node of the
  // strip, nearer its end, may find mass there, and the cell's integral will.
  bool zeroAt(double x, size_t& k) const {
    if (at.empty() || x <= at.front() || x >= at.back()) return false;
    while (at[k + 1] < x) ++k;
    return zero[k];
  }
};

// The cumulative distribution of consecutive leaves, each resolved into steps by integrating
// the polynomial that interpolates its values at the rule's nodes (the rule is interpolatory:
// the steps sum to its value). Where the density is not smooth that polynomial may dip: the
// steps are kept monotone, within the leaf's own value. The inverse-CDF construction of
// Pharr, Jakob and Humphreys, Physically Based Rendering, 4th ed., §A.5.6, on a tabulated
// distribution.
Knots knotsOf(const std::vector<const QuadratureLeaf*>& leaves, int n) {
  double total = 0;
  for (const QuadratureLeaf* l : leaves) total += l->value;
  Knots k;
  double base = 0;
  for (const QuadratureLeaf* l : leaves) {
    if (k.at.empty()) k.at.push_back(l->a), k.cum.push_back(0);
    if (!(l->value > 0)) {
      k.add(l->b, base, true);
      continue;
    }
    const int steps = stepsFor(l->value, total, n);
    const std::vector<double> c = leafCumulative(*l, steps);
    double previous = 0;
    for (int j = 0; j < steps; ++j) {
      const double v = j + 1 == steps ? l->value : std::clamp(c[j], previous, l->value);
      k.add(j + 1 == steps ? l->b : l->a + (l->b - l->a) * (j + 1) / steps, base + v, false);
      previous = v;
    }
    base += l->value;
  }
  return k;
}

// Σ weight·distribution over [lo, hi], as pieces between the union of their knots.
std::vector<Piece> piecesOf(const std::vector<std::pair<double, Knots>>& parts, double lo,
                            double hi) {
  std::vector<double> x{lo, hi};
  for (const auto& [w, k] : parts) x.insert(x.end(), k.at.begin(), k.at.end());
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  std::erase_if(x, [&](double v) { return v < lo || v > hi; });
  std::vector<double> cum(x.size(), 0);
  std::vector<char> zero(x.size() - 1, 1);
  for (const auto& [w, k] : parts) {
    if (k.at.empty()) continue;
    size_t i = 0, j = 0;
    for (size_t u = 0; u < x.size(); ++u) cum[u] += w * k(x[u], i);
    for (size_t u = 0; u + 1 < x.size(); ++u)
      if (zero[u] && !k.zeroAt(0.5 * (x[u] + x[u + 1]), j)) zero[u] = 0;
  }
  std::vector<Piece> pieces;
  for (size_t u = 0; u + 1 < x.size(); ++u)
    pieces.push_back({x[u], x[u + 1], zero[u] ? 0 : std::max(0.0, cum[u + 1] - cum[u]),
                      static_cast<bool>(zero[u])});
  return pieces;
}

// The cumulative distribution over the pieces, linear inside each.
class Cumulative {
 public:
  explicit Cumulative(std::vector<Piece> pieces) : pieces_(std::move(pieces)) {
    cum_.push_back(0);
    for (const Piece& p : pieces_) cum_.push_back(cum_.back() + p.mass);
  }
  double total() const { return cum_.back(); }
  double at(double x) const {
    for (size_t k = 0; k < pieces_.size(); ++k) {
      const Piece& p = pieces_[k];
      if (x <= p.b) return cum_[k] + (x <= p.a ? 0 : p.mass * (x - p.a) / (p.b - p.a));
    }
    return total();
  }
  // The abscissa where the distribution reaches t ∈ (0, total): inside a piece of mass.
  double inverse(double t) const {
    for (size_t k = 0; k < pieces_.size(); ++k) {
      const Piece& p = pieces_[k];
      if (p.mass > 0 && t <= cum_[k + 1])
        return std::clamp(p.a + (t - cum_[k]) / p.mass * (p.b - p.a), p.a, p.b);
    }
    return pieces_.back().b;
  }
  const std::vector<Piece>& pieces() const { return pieces_; }

 private:
  std::vector<Piece> pieces_;
  std::vector<double> cum_;
};

// Maximal runs of pieces where the density is zero, as [a, b].
std::vector<std::pair<double, double>> zeroRuns(const std::vector<Piece>& pieces) {
  std::vector<std::pair<double, double>> runs;
  for (const Piece& p : pieces) {
    if (!p.zero) continue;
    if (!runs.empty() && runs.back().second == p.a)
      runs.back().second = p.b;
    else
      runs.emplace_back(p.a, p.b);
  }
  return runs;
}

// n + 1 edges from lo to hi cutting the pieces into n of about equal mass. A zero run at an
// end of the range is a cell of its own, and so is an interior one at least a uniform cell
// wide (where the grid would have had an empty cell); the runs of mass between them share
// the other cells in proportion to their mass (largest remainders, at least one each), and
// each is cut by inverting the distribution.
std::vector<double> equalMassEdges(const Cumulative& cdf, double lo, double hi, int n) {
  std::vector<std::pair<double, double>> zeros;
  for (const auto& [a, b] : zeroRuns(cdf.pieces()))
    if (!(a == lo && b == hi) && (a == lo || b == hi || b - a >= (hi - lo) / n))
      zeros.emplace_back(a, b);
  // The runs of mass between the zero runs kept.
  auto massRuns = [&] {
    std::vector<std::pair<double, double>> runs;
    double from = lo;
    for (const auto& [a, b] : zeros) {
      if (a > from) runs.emplace_back(from, a);
      from = b;
    }
    if (from < hi) runs.emplace_back(from, hi);
    return runs;
  };
  std::vector<std::pair<double, double>> runs = massRuns();
  auto cellsLeft = [&] { return n - static_cast<int>(zeros.size()); };
  if (cellsLeft() < static_cast<int>(runs.size())) {  // too few cells: the ends' runs only
    std::erase_if(zeros, [&](const auto& z) { return z.first != lo && z.second != hi; });
    if (cellsLeft() < 1) zeros.clear();
    runs = massRuns();
  }
  const int m = cellsLeft();
  std::vector<double> quota, mass;
  std::vector<int> count;
  for (const auto& [a, b] : runs) {
    mass.push_back(cdf.at(b) - cdf.at(a));
    quota.push_back(m * mass.back() / cdf.total());
    count.push_back(std::max(1, static_cast<int>(quota.back())));
  }
  auto sum = [&] {
    int s = 0;
    for (int c : count) s += c;
    return s;
  };
  while (sum() < m) {
    size_t k = 0;
    for (size_t r = 1; r < runs.size(); ++r)
      if (quota[r] - count[r] > quota[k] - count[k]) k = r;
    ++count[k];
  }
  while (sum() > m) {
    size_t k = runs.size();
    for (size_t r = 0; r < runs.size(); ++r)
      if (count[r] > 1 && (k == runs.size() || count[r] - quota[r] > count[k] - quota[k])) k = r;
    --count[k];
  }
  std::vector<double> edges{lo};
  size_t z = 0, r = 0;
  while (z < zeros.size() || r < runs.size()) {
    if (r == runs.size() || (z < zeros.size() && zeros[z].first < runs[r].first)) {
      edges.push_back(zeros[z++].second);
      continue;
    }
    const double start = cdf.at(runs[r].first);
    for (int k = 1; k < count[r]; ++k) edges.push_back(cdf.inverse(start + mass[r] * k / count[r]));
    edges.push_back(runs[r++].second);
  }
  edges.back() = hi;
  return edges;
}

}  // namespace

namespace {

// The marginal distribution in x: the outer leaves of the nested integral over the whole
// rectangle, which starts from kSplit·n / kLeafSteps equal pieces (the leaves' steps then hold
// about 1/(kSplit·n) of a uniform density's mass each), its scale set by a pilot rule.
Task<Cumulative> marginalOf(Density& f, const Domain& grid, const DensityFeatures& features,
                            const QuadratureOptions& options) {
  const CellBounds all{grid.x0, grid.x1, grid.y0, grid.y1};
  DensityFeatures cut = features;
  const int first = static_cast<int>(std::ceil(kSplit * grid.nx / kLeafSteps));
  for (int k = 1; k < first; ++k) cut.breaksX.push_back(grid.x0 + (grid.x1 - grid.x0) * k / first);
  const std::vector<OuterLeaf> outer = co_await tabulateRectangleToItsMass(
      f, cut, grid, all, [options](double mass) { return tabulationOptions(options, mass); },
      leafShare(grid.nx), 0);
  std::vector<const QuadratureLeaf*> leaves;
  for (const OuterLeaf& o : outer) leaves.push_back(&o.leaf);
  co_return Cumulative(piecesOf({{1.0, knotsOf(leaves, grid.nx)}}, grid.x0, grid.x1));
}

// The grid where the marginal has no mass to follow, saying so.
std::optional<Domain> withoutMass(const Domain& grid, const Cumulative& marginal) {
  if (marginal.total() > 0 && std::isfinite(marginal.total())) return std::nullopt;
  Domain d = grid;
  d.gridReason = fmt::format(
      "equal-probability cells need mass to follow, but the quadrature found {:.3g}: the "
      "claimed pdf integrates to 0, or a lobe lies between the rule's nodes (declare it: "
      "Subject::peaks)",
      marginal.total());
  return d;
}

// The cells' x edges, with room for every strip's y edges.
Domain stripsOf(const Domain& grid, const Cumulative& marginal) {
  Domain d = grid;
  d.xEdges = equalMassEdges(marginal, grid.x0, grid.x1, grid.nx);
  d.yEdges.resize(static_cast<size_t>(grid.nx) * (grid.ny + 1));
  return d;
}

// The strip [xa, xb] that the partition's strip i covers, over its support, and what its
// tabulation integrates to.
CellBounds stripOf(const Domain& grid, const Domain& cells, int i) {
  const double xa = cells.xEdges[i], xb = cells.xEdges[i + 1];
  const std::pair<double, double> support = grid.supportY(xa, xb);
  return {xa, xb, support.first, support.second};
}
QuadratureOptions stripOptions(const QuadratureOptions& options, const Cumulative& marginal,
                               const CellBounds& strip) {
  return tabulationOptions(options, marginal.at(strip.x1) - marginal.at(strip.x0));
}

// The profile along y at the strips' edge k. The rule's nodes never reach a strip's ends: a
// support that moves with x (a horizon in a rotated frame) reaches furthest there, and a cell
// taken for empty where an end has mass would receive samples. Computed once for the two
// strips that share the edge, as the nested integral over the strip after it (before it, for
// the last) would compute it.
Task<Profile> edgeProfile(Density& f, const Domain& grid, const DensityFeatures& features,
                          const QuadratureOptions& options, const Cumulative& marginal,
                          const Domain& cells, int k) {
  const CellBounds strip = stripOf(grid, cells, std::min(k, grid.nx - 1));
  Profile p;
  if (strip.x1 > strip.x0 && strip.y1 > strip.y0)
    p = co_await profileAlongY(f, features, grid, strip, stripOptions(options, marginal, strip),
                               cells.xEdges[k]);
  co_return p;
}

// Strip i's y edges: its conditional distribution, Σ over the outer rule's nodes x_k of
// w_k ∫ f(x_k, y) dy up to y, from the profiles along y that the nested integral over the strip
// computes at its nodes (each cut at the density's jumps at its own x, graded towards the
// peaks). The profiles at its ends weigh nothing; they only find mass where every node found
// none.
Task<std::vector<double>> stripEdges(Density& f, const Domain& grid,
                                     const DensityFeatures& features,
                                     const QuadratureOptions& options, const Cumulative& marginal,
                                     const Domain& cells, int i,
                                     std::array<const Profile*, 2> ends) {
  const CellBounds strip = stripOf(grid, cells, i);
  const double lo = strip.y0, hi = strip.y1;
  std::vector<double> edges;
  if (strip.x1 > strip.x0 && hi > lo) {
    const std::vector<OuterLeaf> outer = co_await tabulateRectangle(
        f, features, grid, strip, stripOptions(options, marginal, strip), 0, leafShare(grid.ny));
    std::vector<std::pair<double, Knots>> parts;
    auto add = [&](double weight, const Profile& p) {
      std::vector<const QuadratureLeaf*> leaves;
      for (const QuadratureLeaf& l : p.leaves) leaves.push_back(&l);
      parts.emplace_back(weight, knotsOf(leaves, grid.ny));
    };
    for (const Profile* p : ends) add(0.0, *p);
    for (const OuterLeaf& o : outer) {
      const std::array<double, kRuleNodes> w = ruleWeights(o.leaf.a, o.leaf.b);
      for (size_t k = 0; k < kRuleNodes; ++k) add(w[k], o.profiles[k]);
    }
    const Cumulative conditional(piecesOf(parts, lo, hi));
    if (conditional.total() > 0) edges = equalMassEdges(conditional, lo, hi, grid.ny);
  }
  if (edges.empty())  // a strip without mass: the grid's edges
    for (int j = 0; j <= grid.ny; ++j) edges.push_back(grid.yEdge(i, j));
  // The end cells reach the rectangle's edges, so that every point of it has a cell.
  edges.front() = grid.y0;
  edges.back() = grid.y1;
  co_return edges;
}

// The marginal in one computation, then the profiles at the strips' edges, then every strip.
Task<Domain> cellsOf(Density& f, const Domain& grid, const DensityFeatures& features,
                     QuadratureOptions options) {
  const Cumulative marginal = co_await marginalOf(f, grid, features, options);
  if (auto d = withoutMass(grid, marginal)) co_return *d;
  Domain d = stripsOf(grid, marginal);
  std::vector<Task<Profile>> atEdges;
  atEdges.reserve(grid.nx + 1);
  for (int k = 0; k <= grid.nx; ++k)
    atEdges.push_back(edgeProfile(f, grid, features, options, marginal, d, k));
  const std::vector<Profile> profiles = co_await f.all(std::move(atEdges), true);
  std::vector<Task<std::vector<double>>> strips;
  strips.reserve(grid.nx);
  for (int i = 0; i < grid.nx; ++i)
    strips.push_back(
        stripEdges(f, grid, features, options, marginal, d, i, {&profiles[i], &profiles[i + 1]}));
  const std::vector<std::vector<double>> edges = co_await f.all(std::move(strips), true);
  for (int i = 0; i < grid.nx; ++i)
    std::copy(edges[i].begin(), edges[i].end(),
              d.yEdges.begin() + static_cast<size_t>(i) * (grid.ny + 1));
  co_return d;
}

}  // namespace

Domain equalProbabilityCells(const Domain& grid, const DensityFn& f,
                             const DensityFeatures& features, const QuadratureOptions& options) {
  Density d(f);
  return d.run(cellsOf(d, grid, features, options));
}

Domain equalProbabilityCells(const Domain& grid, const DensityBatchFn& f,
                             const DensityFeatures& features, const QuadratureOptions& options) {
  Density d(f);
  return d.run(cellsOf(d, grid, features, options));
}

Domain cellsFor(const Domain& grid, CellLayout layout, const DensityFn& f,
                const DensityFeatures& features, const QuadratureOptions& options) {
  return layout == CellLayout::Grid ? grid : equalProbabilityCells(grid, f, features, options);
}

Domain cellsFor(const Domain& grid, CellLayout layout, const DensityBatchFn& f,
                const DensityFeatures& features, const QuadratureOptions& options) {
  return layout == CellLayout::Grid ? grid : equalProbabilityCells(grid, f, features, options);
}

}  // namespace verity::chi2
