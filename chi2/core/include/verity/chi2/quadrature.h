// Expected cell probabilities: the density integrated over each cell of a domain by nested
// adaptive Gauss–Kronrod quadrature (15-point Kronrod extension of the 7-point Gauss rule,
// Boost.Math), in double precision. Each cell is integrated separately, so a lobe that is
// narrow compared with the cell is refined where it lies rather than missed by a fixed
// midpoint or trapezoid rule.
#pragma once

#include <verity/chi2/domain.h>

#include <functional>
#include <vector>

namespace verity::chi2 {

// A density with respect to dx dy on a domain; must be safe to call from several threads.
using DensityFn = std::function<double(double x, double y)>;
// The density at every point of a batch, values[k] = f(points[k]): one call for many points,
// for SIMD or GPU code, or a density written in NumPy, whose cost is in the call rather than
// in the point. Called from the thread that called the integral or partition given it.
using DensityBatchFn =
    std::function<void(const std::vector<Point2d>& points, std::vector<double>& values)>;
// The points a batch gathers, from every computation waiting for values, before it is
// evaluated: a call holds at least this many but at the end of a computation, and at most
// 2¹⁸ (larger batches are evaluated in calls of 2¹⁸).
inline constexpr size_t kDensityBatchPoints = size_t(1) << 14;
// Abscissae in y at which the density may jump, at a given x (may be empty).
using BreakpointFn = std::function<std::vector<double>(double x)>;

// What the quadrature is told about a density's shape so that it splits its ranges there
// rather than refining a jump or a spike to its maximum depth.
struct DensityFeatures {
  BreakpointFn breaksY;         // jumps in y at a given x
  std::vector<double> breaksX;  // abscissae where the density jumps or kinks for all y
  std::vector<Point2d> peaks;   // lobes far narrower than a cell: cuts graded towards them
  // The abscissae where the jumps of breaksY pass through a given height y: a rectangle's
  // outer range is split where they meet its lower and upper edges (Subject::
  // breakpointCrossingsX).
  BreakpointFn crossingsX;
};

struct QuadratureOptions {
  // The inner integrals stop refining once their error estimate falls below this fraction
  // of their L1 norm, or after maxDepth bisections. Densities are evaluated in single
  // precision (relative noise ~1e-7, amplified by exp() and by cancellations), so a tighter
  // tolerance only buys refinement of noise (measured: 10-30x slower at 1e-6). What the
  // chi-square test needs is far less: cells whose probabilities are off by a relative δ
  // add about N·δ² to the statistic's noncentrality, which at δ = 1e-4 stays below 1 for
  // up to 10⁸ samples (a test's budget), against the hundreds that the effects it states
  // add. Measured on 41 configurations of the sweep (every 30th material): at 1e-4 rather
  // than 1e-5 the quadrature took 35% less time, no statistic moved by more than 0.03 and
  // the largest summed error estimate stayed 2.7e-6.
  double relTolerance = 1e-4;
  // The outer integral sees the inner integrals' errors as noise, so it is looser.
  double outerRelTolerance = 1e-4;
  // Declared jumps and peaks are resolved by graded cuts, so a piece still unconverged after
  // six bisections is a staircase of the single-precision density (grazing Beckmann and GGX,
  // an index near 1: steps of 1-4%), which more depth only refines. Measured on 22 sample
  // tests against depth 11 and 10x tighter tolerances: total error 7.8e-7 at depth 6,
  // 5.9e-7 at depth 8, 1.0e-5 at depth 4; a full sweep at depth 6 runs 20% faster.
  unsigned maxDepth = 6;
  // The whole grid's error budget, shared equally by the cells: a cell whose pilot
  // estimate is small is integrated to a looser relative tolerance, never looser than
  // maxRelTolerance. With 2,048 cells and 10⁶ samples this is far below both the
  // integral check's tolerance and the chi-square test's resolution (√(N·p) counts).
  double gridAbsTolerance = 2e-5;
  double maxRelTolerance = 1e-2;
  // Set per cell from gridAbsTolerance: an absolute error that every piece may claim its
  // share of, so that pieces a few ulps wide (graded towards a peak) stop refining.
  double cellAbsTolerance = 0;
  // A cell whose error estimate exceeds the tolerance it was integrated to (its share of
  // gridAbsTolerance, or relTolerance of its pilot estimate where that is larger: a cell
  // holding more than share/relTolerance of the mass cannot meet its share in single
  // precision) is integrated again with this many more bisections and ten times tighter
  // tolerances, and the two levels are compared (integrateCell); 0 turns the comparison
  // off. The grid's summed estimate is therefore about gridAbsTolerance + relTolerance·∫f
  // at most (1.2·10⁻⁴ for a pdf); in practice a few per cent of that (each piece stops
  // once under its share, and Gauss–Kronrod's estimate bounds the 7-point rule's error, not
  // the 15-point value's). A test whose estimate exceeds the integral check's tolerance
  // (10⁻⁴) is INCONCLUSIVE, never passed (TestResult::quadratureHolds).
  unsigned verifyDepth = 2;
};

struct CellIntegral {
  double value = 0;
  // Error estimate in the integral's units: the outer rule's |K15 − G7| plus the inner
  // integrals' estimates integrated over x by the outer rule's own weights; for a cell
  // compared at two refinement levels, the smaller of that and the levels' difference.
  double error = 0;
  // The part of `error` that is round-off noise: pieces whose halves' estimates stayed at
  // the whole's size (a density evaluated in single precision is a staircase of rounding
  // steps there). Their errors along one line are independent draws of either sign, added
  // in quadrature; a second level stops at the same pieces, so its agreement with the first
  // says nothing of them, and the comparison of levels keeps this part.
  double noise = 0;
};

// ∫∫ f over a rectangle of the domain, clipped by its support, split at the features (the
// peaks inside it or within half its size of it), to the options as given: one nested
// adaptive integral, with no share of a grid's budget and no second level.
CellIntegral integrateRectangle(const DensityFn& f, const DensityFeatures& features,
                                const Domain& domain, const CellBounds& rectangle,
                                const QuadratureOptions& options);
// One cell (domain.cell(cell), whatever the layout) to its share of gridAbsTolerance.
CellIntegral integrateCell(const DensityFn& f, const DensityFeatures& features,
                           const Domain& domain, int cell, const QuadratureOptions& options);
// All cells, in parallel over cells.
std::vector<CellIntegral> integrateGrid(const DensityFn& f, const Domain& domain,
                                        const QuadratureOptions& options,
                                        const DensityFeatures& features = {});
// The same figures, bit for bit, from a density evaluated in batches: every cell's refinement
// advances together, so each call holds every node that the next level of every cell needs
// (one call per level of the nested rules, each point evaluated once).
std::vector<CellIntegral> integrateGrid(const DensityBatchFn& f, const Domain& domain,
                                        const QuadratureOptions& options,
                                        const DensityFeatures& features = {});

// One-dimensional adaptive integral to max(relTolerance · |∫f|, absTolerance).
double integrate1D(const std::function<double(double)>& f, double a, double b,
                   const QuadratureOptions& options, double* error = nullptr,
                   double absTolerance = 0);
// Nested 2D integral over [x0,x1] × [y0,y1].
double integrate2D(const DensityFn& f, double x0, double x1, double y0, double y1,
                   const QuadratureOptions& options, double* error = nullptr);

}  // namespace verity::chi2
