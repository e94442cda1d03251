// Pearson's chi-square goodness-of-fit test of observed cell counts against expected
// counts, with the pooling rule of the usual sampling tests (Nori, Mitsuba, pbrt): cells
// whose expected count is below 5 are pooled into one cell, which is kept (merged into the
// smallest regular cell if the pool itself expects fewer than 5), never dropped.
#pragma once

#include <string>
#include <vector>

namespace verity::chi2 {

struct ChiSquareResult {
  double statistic = 0;
  int dof = 0;
  double pValue = 1;
  int regularCells = 0;  // cells tested on their own
  int pooledCells = 0;   // cells merged into the pool
  double pooledExpected = 0;
  // Samples in a cell whose expected count is below the outright threshold: a sample where
  // the density is (numerically) zero is a failure whatever the statistic says.
  long long outrightSamples = 0;
  int outrightCell = -1;
  double outrightExpected = 0;
  double outrightThreshold = 0;
  bool degenerate = false;  // fewer than two cells left: no test possible
  bool passed(double significance) const {
    return outrightSamples == 0 && (degenerate || pValue >= significance);
  }
  std::string describe() const;
};

// `expected` and `observed` per cell (same totals up to the caller's normalisation). Cells
// whose expected count is below `outrightThreshold` and which hold a sample fail outright.
ChiSquareResult chiSquareTest(const std::vector<double>& expected,
                              const std::vector<long long>& observed, double outrightThreshold);

// The dof the test will have when the cells expect these counts (the same pooling rule);
// 0 when fewer than two cells remain. A check that sizes its sample count plans with it.
int plannedDof(const std::vector<double>& expected);

// The outright threshold used by the suite: with `cells` cells, the chance that a correct
// sampler puts any sample in a cell expecting fewer than τ samples is at most cells · τ;
// τ = 10⁻³ · α / cells keeps it at a thousandth of the per-test level α.
double outrightThreshold(double significance, int cells);

}  // namespace verity::chi2
