// Cells that follow the density. On the uniform grid a narrow lobe falls into a handful of
// cells (Phong with exponent 10⁴ at 30°: 4 cells expect 5 samples or more), so an error
// inside the lobe is invisible at any sample count. Cells of nearly equal probability under
// the claimed pdf keep every cell's expected count near N/K wherever the mass lies: the
// rectangle is cut into nx strips of about 1/nx of the mass each by inverting the marginal
// distribution in x, and each strip into ny cells by inverting its conditional distribution
// in y (the inverse-CDF construction of a sampling distribution, e.g. Pharr, Jakob and
// Humphreys, Physically Based Rendering, 4th ed., §A.5.6, "2D Sampling with Multidimensional
// Transformations", applied to cell edges rather than to samples).
#pragma once

#include <verity/chi2/domain.h>
#include <verity/chi2/quadrature.h>

namespace verity::chi2 {

enum class CellLayout {
  // Cells holding about 1/(nx·ny) of the claimed pdf's mass each: a narrow lobe keeps as many
  // cells, and degrees of freedom, as a diffuse one.
  EqualProbability,
  // The uniform grid of the domain: TestOptions' default (the sweep's), much cheaper to integrate.
  // Every
  // equal-probability cell of a narrow lobe lies where a density evaluated in single
  // precision is a staircase (Phong with exponent 10⁴: steps of 6·10⁻⁴), which the per-cell
  // quadrature refines to its limits, where the grid meets it in four cells (measured: 0.15 s
  // against 8-10 s for the cells' integrals). It also keeps the cells independent of the
  // claimed pdf, for comparing histograms cell by cell or reading a figure by coordinates.
  Grid,
};

std::string cellLayoutName(CellLayout layout);  // "equal" or "grid", as `verity chi2 --cells`
// The layout named "equal" or "grid"; std::invalid_argument naming `option` otherwise.
CellLayout parseCellLayout(const std::string& name, const std::string& option = "--cells");

// The grid's rectangle cut into grid.nx × grid.ny cells of nearly equal probability under f,
// whose features guide the quadrature as for integrateGrid. The distributions are tabulated by
// the quadrature's own nested Gauss–Kronrod rule and error control (to 10⁻³ inner, 10⁻²
// outer, no verifying level), keeping its leaves: the marginal in x from the outer leaves of
// the integral over the whole rectangle (each node's inner integral over the full range of
// y), then each strip's conditional in y as Σ w_k ∫ f(x_k, y) dy over the nodes x_k of the
// integral over the strip, each profile along y cut at the jumps and graded towards the peaks
// at its own x. Inside a leaf the distribution is the integral of the polynomial that
// interpolates the rule's values (kept monotone), in steps of about 1/(4n) of the mass to be
// cut into n; leaves holding more than 32 such steps are bisected first. An edge is placed by
// linear interpolation inside a step, so a cell's probability is within about ±1/(2K) of 1/K
// for K cells (PartitionTest measures it). The expected counts are then integrated per cell
// by integrateGrid as on the grid. Where f is zero at an end of a strip's range, or over an
// interior run at least a grid cell wide (zero at every node there), that run is a cell of its
// own, expecting nothing, so that a sample there fails outright (chiSquareTest) rather than
// merely adding to a populated cell. The result is deterministic and independent of the number
// of threads.
//
// Cost: a bounded number of density evaluations whatever f does. Each piece's refinement
// stops at QuadratureOptions::maxDepth (or where its halves are round-off noise), and the
// bisection for mass after 12 levels, each bisecting at most 4n/32 leaves (those holding more
// than 32/(4n) of the mass, taken afresh at each level). Measured in evaluations, partition
// against the cells' integrals (FrameworkPartitionCost): a cosine lobe 0.39M against 0.70M, Phong
// 10⁴ 1.05M against 1.22M; Phong 10⁴ evaluated in float (a staircase of 6·10⁻⁴ steps) 4.4M against
// 20.7M. What a capped refinement costs is accuracy of the edges only: where the levels or the
// depth run out, a step holds more than 1/(4n) of the mass and the cells there are less equal,
// never wrong, since their probabilities are integrated accurately afterwards. Where f integrates
// to zero (or to no finite number) there is no mass to follow: the uniform grid is returned, with
// gridReason saying so.
Domain equalProbabilityCells(const Domain& grid, const DensityFn& f,
                             const DensityFeatures& features = {},
                             const QuadratureOptions& options = {});

// The same cells, bit for bit, from a density evaluated in batches (DensityBatchFn): the
// marginal's refinement, then every strip's together, a call per level.
Domain equalProbabilityCells(const Domain& grid, const DensityBatchFn& f,
                             const DensityFeatures& features, const QuadratureOptions& options);

// The cells a sampling test histograms in: `grid` itself, or equalProbabilityCells.
Domain cellsFor(const Domain& grid, CellLayout layout, const DensityFn& f,
                const DensityFeatures& features, const QuadratureOptions& options);
Domain cellsFor(const Domain& grid, CellLayout layout, const DensityBatchFn& f,
                const DensityFeatures& features, const QuadratureOptions& options);

}  // namespace verity::chi2
