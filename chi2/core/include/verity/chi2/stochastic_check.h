// Checking a BSDF whose eval and sample weight are random, unbiased estimates (a layered BSDF
// evaluated by a random walk), or a deterministic BSDF that has no pdf. Neither the chi-square
// test nor the per-sample weight = eval·|cos|/pdf check applies; what must hold is that
// sampling and evaluation estimate the same scattered energy. On the sphere's cells
// (sphereDomain: equal solid angle), for each component:
//   sampled     the mean over N draws of weight·1[wo in the cell] (a draw that returns nothing
//               or a delta sample counts as 0), with its standard error s/√N;
//   evaluated   ∫ E[eval]·|cos θo| dω over the cell, by eval at strata × strata jittered
//               directions uniform in the cell (a stream of its own), with the standard error
//               of strata collapsed in pairs (Cochran 1977), which may overstate it: conservative.
// Each cell's two estimates are compared by Welch's test with the Welch–Satterthwaite degrees
// of freedom (Welch 1947, Biometrika 34; Satterthwaite 1946; <verity/stats/welch_t.h>), and the
// cells by Holm's step-down procedure at the check's level (Holm 1979, Scand. J. Statistics 6;
// <verity/stats/holm.h>), which holds under any dependence. Cells with fewer than
// kStochasticMinHits samples are pooled into one, tested when the pool has that many: the
// Poisson skew of a cell's count, 1/√hits, then changes the normal tail at Holm's thresholds
// by tens of percent at most. The total albedo (all cells) is a second test, its components
// at the Šidák level for their number. So a check is kStatisticalTestsPerStochasticCheck tests
// for the caller's Šidák correction.
//
// The model is called on one thread, in a fixed order: a BSDF that draws its randomness from
// a generator of its own needs no locking, and its check is reproducible if that generator's
// seed is fixed. pdf() and a sample's pdf are not used. Weights and evals may be negative (an
// unbiased estimator may be); NaN or infinite ones, and non-unit directions, are defects.
#pragma once

#include <verity/chi2/bsdf_model.h>
#include <verity/chi2/check_result.h>

#include <string>
#include <type_traits>
#include <vector>

namespace verity::chi2 {

inline constexpr int kStatisticalTestsPerStochasticCheck = 2;  // the cells (Holm), the total
inline constexpr long long kStochasticMinHits = 1000;

// `resolution` 0 gives 8 cells in cos θ (16 in φ).
struct StochasticCheckOptions : CheckOptions {
  int strata = 32;  // each cell's eval at strata × strata jittered directions; even
};

// Two independent estimates of one mean, compared by Welch's test.
struct WelchComparison {
  double sampled = 0, sampledError = 0;      // the mean and its standard error
  double evaluated = 0, evaluatedError = 0;  //
  double t = 0, df = 0, p = 1;               // two-sided
};

struct StochasticCellTest : WelchComparison {
  int cell = -1;  // −1: the pooled cells
  int component = 0;
  long long hits = 0;  // draws whose direction fell in the cell (or the pool)
  bool rejected = false;
};

struct StochasticCheck {
  std::string subject;
  double significance = 0;
  long long samples = 0, hits = 0, deltaSamples = 0, evaluations = 0;
  int cells = 0, components = 3, pooledCells = 0;
  std::vector<WelchComparison> total;  // per component: the albedo
  bool totalPassed = true;
  std::vector<StochasticCellTest> cellTests;
  int rejections = 0;  // Holm's
  // What it could have caught, with 90% power (normal approximation): the smallest relative
  // error of the total albedo (the worst component), and of one cell's mean at Holm's first
  // threshold α/m (the best cell).
  double detectableTotal = 0, detectableCell = 0;
  Audit audit;
  double seconds = 0;

  // FAILED on a defect; else INCONCLUSIVE when fewer than kStochasticMinHits draws returned a
  // non-delta direction, or nothing scatters (all zero); else FAILED when the total or Holm
  // rejects; else PASSED.
  Verdict verdict() const;
  std::string inconclusiveReason() const;
  bool passed() const { return verdict() == Verdict::Passed; }
  // "total albedo", "cells", "inconclusive" and the audit's defects; empty when passed.
  std::vector<std::string> failures() const;
  bool failed(const std::string& check) const;
  std::string report() const;
};

// One incident direction wi (local frame, normalised here).
StochasticCheck checkStochasticBsdf(const BsdfModel& model, const Eigen::Vector3d& wi,
                                    const StochasticCheckOptions& options);

template <class V, class = std::enable_if_t<!std::is_same_v<V, Eigen::Vector3d>>>
StochasticCheck checkStochasticBsdf(const BsdfModel& model, const V& wi,
                                    const StochasticCheckOptions& options) {
  return checkStochasticBsdf(model, readVector3(wi), options);
}

}  // namespace verity::chi2
