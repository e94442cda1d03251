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

// A piece [a, b] of a range and the mass the density holds over it.
struct Piece {
  double a = 0, b = 0, mass = 0;
};

// A piece holding more than 1/(kSplit·n) of the mass to be cut into n is bisected: an edge
// placed by linear interpolation inside a piece then errs by at most that much, and by far
// less where the density is smooth across the piece (second order in its width).
constexpr double kSplit = 4;
// Pieces narrower than this fraction of the range are not bisected: densities are evaluated
// in single precision, whose steps (~10⁻⁷ relative) are coarser.
constexpr double kMinWidth = 1e-9;

// The masses of the inversion's pieces need only be good to a few per cent: one bisection at
// most per range, and tolerances that a density evaluated in single precision can meet. A
// piece that holds much of the mass is bisected by the inversion anyway, and the cells' own
// probabilities are integrated afterwards to the test's tolerances (integrateGrid).
// Measured on a Phong lobe of exponent 10⁴ (a staircase of 6·10⁻⁴ steps): 6.5 s with two
// bisections, 1 s with none; with none a Gaussian of σ = 0.01 in pieces of 1/8 got cells of
// 4.7 times their share (FrameworkPartition.DiskAndTriangleSupportsAreCut).
QuadratureOptions inversionOptions(QuadratureOptions o) {
  o.relTolerance = 1e-3;
  o.outerRelTolerance = 1e-2;
  o.maxDepth = 1;
  o.verifyDepth = 0;
  o.cellAbsTolerance = 0;
  return o;
}

// What the inversion integrates: the loose rule, or the grid's accurate one (as integrateGrid
// integrates a cell, to a grid cell's share of the budget).
struct Integrals {
  const Domain& grid;
  const DensityFeatures& features;
  QuadratureOptions loose, accurate;

  Integrals(const Domain& g, const DensityFeatures& f, const QuadratureOptions& options)
      : grid(g), features(f), loose(inversionOptions(options)), accurate(options) {
    accurate.cellAbsTolerance = options.gridAbsTolerance / grid.cells();
  }
};

// The mass over [a, b], by the inversion's rule or `accurate`ly (to the test's own
// tolerances): of the marginal in x (over the grid's height), or of the strip [xa, xb]'s
// conditional in y.
struct MassOf {
  Density& density;
  const Integrals& integral;
  bool inY = false;
  double xa = 0, xb = 0;

  Task<double> operator()(double a, double b, bool accurate) const {
    const Domain& g = integral.grid;
    const CellBounds r = inY ? CellBounds{xa, xb, a, b} : CellBounds{a, b, g.y0, g.y1};
    const CellIntegral c = co_await rectangleIntegral(
        density, integral.features, g, r, accurate ? integral.accurate : integral.loose);
    co_return c.value;
  }
};

// Halves whose rule-of-thumb masses lose half their parent's have missed a lobe between the
// rule's nodes (Phong with exponent 10⁶: a lobe 10⁻³ wide): they are integrated accurately.
Task<std::vector<Piece>> bisect(const MassOf& mass, Piece p, double most, double minWidth) {
  if (!(p.mass > most) || p.b - p.a <= minWidth) co_return std::vector<Piece>{p};
  Density& d = mass.density;
  const double m = 0.5 * (p.a + p.b);
  std::array<double, 2> halves = co_await d.both(mass(p.a, m, false), mass(m, p.b, false));
  Piece left{p.a, m, halves[0]}, right{m, p.b, halves[1]};
  if (left.mass + right.mass < 0.5 * p.mass) {
    halves = co_await d.both(mass(p.a, m, true), mass(m, p.b, true));
    left.mass = halves[0];
    right.mass = halves[1];
  }
  std::array<std::vector<Piece>, 2> parts =
      co_await d.both(bisect(mass, left, most, minWidth), bisect(mass, right, most, minWidth));
  parts[0].insert(parts[0].end(), parts[1].begin(), parts[1].end());
  co_return std::move(parts[0]);
}

// [lo, hi] cut at `cuts` and into n equal pieces, each bisected until it holds at most
// 1/(kSplit·n) of the total: the pieces in order, their masses summing to the total. In
// parallel over the first pieces, each refined alone: the same pieces for any thread count.
// The first pieces are integrated accurately where their rule-of-thumb masses sum to less
// than half of `expected` (or always, without an expectation: a lobe between the rule's
// nodes would leave no mass to follow).
Task<std::vector<Piece>> massPieces(const MassOf& mass, double lo, double hi, int n,
                                    std::vector<double> cuts, double expected) {
  Density& d = mass.density;
  for (int k = 1; k < n; ++k) cuts.push_back(lo + (hi - lo) * k / n);
  cuts.push_back(lo);
  cuts.push_back(hi);
  std::erase_if(cuts, [&](double c) { return !(c >= lo && c <= hi); });
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const size_t count = cuts.size() - 1;
  std::vector<Piece> first(count);
  double total = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const bool accurate = pass == 1;
    if (accurate && total >= 0.5 * expected) break;
    std::vector<Task<double>> masses;
    masses.reserve(count);
    for (size_t k = 0; k < count; ++k) masses.push_back(mass(cuts[k], cuts[k + 1], accurate));
    const std::vector<double> m = co_await d.all(std::move(masses), true);
    total = 0;
    for (size_t k = 0; k < count; ++k) {
      first[k] = {cuts[k], cuts[k + 1], m[k]};
      total += m[k];
    }
  }
  std::vector<Task<std::vector<Piece>>> refining;
  refining.reserve(count);
  for (size_t k = 0; k < count; ++k)
    refining.push_back(bisect(mass, first[k], total / (kSplit * n), kMinWidth * (hi - lo)));
  const std::vector<std::vector<Piece>> refined = co_await d.all(std::move(refining), true);
  std::vector<Piece> pieces;
  for (const auto& r : refined) pieces.insert(pieces.end(), r.begin(), r.end());
  co_return pieces;
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
    if (p.mass > 0) continue;
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

// The marginal distribution in x.
Task<Cumulative> marginalOf(Density& f, const Integrals& integral) {
  const Domain& grid = integral.grid;
  const MassOf mass{f, integral};
  std::vector<Piece> pieces =
      co_await massPieces(mass, grid.x0, grid.x1, grid.nx, integral.features.breaksX,
                          std::numeric_limits<double>::infinity());
  co_return Cumulative(std::move(pieces));
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

// Strip i's y edges, the strip being [cells.xEdges[i], cells.xEdges[i + 1]].
Task<std::vector<double>> stripEdges(Density& f, const Integrals& integral,
                                     const Cumulative& marginal, const Domain& cells, int i) {
  const Domain& grid = integral.grid;
  const double xa = cells.xEdges[i], xb = cells.xEdges[i + 1];
  // The strip's conditional distribution over the support's extent; its jumps taken at
  // the strip's middle (where they move with x, the cells follow them approximately).
  const std::pair<double, double> support = grid.supportY(xa, xb);
  const double lo = support.first, hi = support.second;
  std::vector<double> cuts;
  if (integral.features.breaksY) cuts = integral.features.breaksY(0.5 * (xa + xb));
  std::vector<double> edges;
  if (xb > xa && hi > lo) {
    const MassOf mass{f, integral, true, xa, xb};
    std::vector<Piece> pieces = co_await massPieces(mass, lo, hi, grid.ny, std::move(cuts),
                                                    marginal.at(xb) - marginal.at(xa));
    const Cumulative conditional(std::move(pieces));
    if (conditional.total() > 0) edges = equalMassEdges(conditional, lo, hi, grid.ny);
  }
  if (edges.empty())  // a strip without mass: the grid's edges
    for (int j = 0; j <= grid.ny; ++j) edges.push_back(grid.yEdge(i, j));
  // The end cells reach the rectangle's edges, so that every point of it has a cell.
  edges.front() = grid.y0;
  edges.back() = grid.y1;
  co_return edges;
}

// The marginal in one computation, then every strip.
Task<Domain> cellsOf(Density& f, const Domain& grid, const DensityFeatures& features,
                     QuadratureOptions options) {
  const Integrals integral(grid, features, options);
  const Cumulative marginal = co_await marginalOf(f, integral);
  if (auto d = withoutMass(grid, marginal)) co_return *d;
  Domain d = stripsOf(grid, marginal);
  std::vector<Task<std::vector<double>>> strips;
  strips.reserve(grid.nx);
  for (int i = 0; i < grid.nx; ++i) strips.push_back(stripEdges(f, integral, marginal, d, i));
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
