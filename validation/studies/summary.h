// Summaries of study results: log-log slopes with confidence intervals, efficiencies, the
// most efficient integrator, speed-ups. The report prints these numbers; the plots are
// drawn from the same records by reports/make_report.py.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "validation/studies/budget.h"
#include "validation/studies/fit.h"
#include "validation/studies/summary_records.h"

namespace verity::studies {

// Groups "convergence" records by (scene, resolution, integrator, sampler, max bounces,
// threads, budget type) and fits log relMSE against log wall time and against log spp over all runs
// (every run is one point), and log of the mean relMSE over the runs at each budget against log spp
// ("fit_spp_of_means"): the per-run fit follows E[log relMSE], which for a heavy-tailed
// estimator rises towards log E[relMSE] as the budget grows (rare large samples are missed
// more often at small budgets), so it can be flatter than −1 for an unbiased estimator; the
// mean over runs is unbiased for E[relMSE] = A/spp + B whatever the tails. Efficiency = 1 / (relMSE
// · wall time) (Veach 1997, section 2.4: the efficiency of an estimator is 1 / (variance · time));
// a group's efficiency is the median over its runs at its largest budget, where fixed per-render
// costs weigh least. Per (scene, resolution, sampler, budget type, threads), "best" names the most
// efficient integrator and its ratio to every other. A group of a sampler whose samples are
// correlated has no rel_variance: its budgets' median_rel_variance is null and the group's
// "rel_variance_omitted" says why. "speedup" records give, per (scene, integrator, spp),
// the median wall time per thread count, speed-up = median time at the fewest threads / median
// time, parallel efficiency = speed-up · fewest threads / threads.
// "strategies" records (one BDPT render each) give, per render, the strategies ranked by
// their share of the image and the fewest of them that carry kCarriedShare of it.
inline constexpr double kCarriedShare = 0.9;
// "time_to_accuracy" of a convergence group: the wall time at which its relative MSE reaches
// each target, from the line fitted to log mean relMSE against log mean wall time over the
// budgets (the mean over runs is unbiased for E[relMSE]), with the inverse-prediction
// interval of that time at the summary's confidence. "equal_time": per (scene, resolution,
// sampler, threads, time budget), every integrator's mean relMSE and its standard error.
inline constexpr double kAccuracyTargets[] = {1e-2, 1e-3};

// The runs of one convergence group at one budget: means (the mean relMSE is unbiased for
// E[relMSE]), their standard errors (NaN below two runs) and medians. medianRelVariance is
// NaN for a sampler whose samples are correlated.
struct BudgetSummary {
  double budget = 0;
  size_t runs = 0;
  double meanRelMse = 0, relMseStdError = 0, meanWallSeconds = 0, wallSecondsStdError = 0;
  double meanSpp = 0;
  double medianRelMse = 0, medianRelVariance = 0, medianWallSeconds = 0, medianCpuSeconds = 0;
  double medianSpp = 0, medianEfficiency = 0;
};

enum class AccuracyStatus { NoFit, Reached, NotReached, BeforeSmallestBudget, SlopeNotSignificant };
// "no fit", "reached", "not reached", "before the smallest budget", "slope not significant".
const char* accuracyStatusName(AccuracyStatus status);

// When a group's relative MSE reaches `targetRelMse`: the estimate and, where `bounded`, its
// interval (none without a fit).
struct TimeToAccuracy {
  double targetRelMse = 0;
  AccuracyStatus status = AccuracyStatus::NoFit;
  double seconds = 0;
  bool bounded = false;
  double secondsLow = 0, secondsHigh = 0;
};

// What makes runs one convergence group; the groups are listed in this order.
struct ConvergenceGroupKey {
  std::string scene;
  int width = 0, height = 0;
  std::string integrator, sampler;
  int maxBounces = 0, threads = 0;
  BudgetType budgetType = BudgetType::Spp;
  auto operator<=>(const ConvergenceGroupKey&) const = default;
};

struct ConvergenceGroup {
  ConvergenceGroupKey key;
  size_t runs = 0;
  double relMseEpsilon = 0, referenceRelMse = 0;
  LineFit fitTime, fitSpp, fitSppOfMeans, fitTimeOfMeans;
  std::vector<TimeToAccuracy> timeToAccuracy;  // one per kAccuracyTargets
  double efficiency = 0;
  std::vector<BudgetSummary> budgets;  // by growing budget
  bool relVarianceOmitted = false;     // the sampler's samples are correlated
};

// The integrators compared for "best": runs of one scene, resolution, sampler, budget type and
// thread count.
struct EfficiencyKey {
  std::string scene;
  int width = 0, height = 0;
  std::string sampler;
  BudgetType budgetType = BudgetType::Spp;
  int threads = 0;
  auto operator<=>(const EfficiencyKey&) const = default;
};

struct BestIntegrator {
  EfficiencyKey key;
  std::string integrator;
  double efficiency = 0;
  std::map<std::string, double> timesBetterThan;  // every integrator, itself included (1)
};

// The integrators compared at equal time: one scene, resolution, sampler, thread count and time
// budget.
struct EqualTimeKey {
  std::string scene;
  int width = 0, height = 0;
  std::string sampler;
  int threads = 0;
  double seconds = 0;
  auto operator<=>(const EqualTimeKey&) const = default;
};

struct EqualTimeCell {
  double meanRelMse = 0, relMseStdError = 0, meanSpp = 0;
  size_t runs = 0;
};

struct EqualTime {
  EqualTimeKey key;
  std::map<std::string, EqualTimeCell> integrators;
};

// The renders timed against each other for a speed-up: one scene, resolution, integrator, max
// bounces and spp.
struct SpeedupKey {
  std::string scene;
  int width = 0, height = 0;
  std::string integrator;
  int maxBounces = 0, spp = 0;
  auto operator<=>(const SpeedupKey&) const = default;
};

struct Speedup {
  SpeedupKey key;
  int threads = 0, baselineThreads = 0;
  size_t repeats = 0;
  double medianWallSeconds = 0, speedup = 0, coresUsed = 0, parallelEfficiency = 0;
};

// The strategies records summarized: one per scene, resolution and max bounces.
struct StrategiesKey {
  std::string scene;
  int width = 0, height = 0, maxBounces = 0;
  auto operator<=>(const StrategiesKey&) const = default;
};

struct StrategiesSummary {
  StrategiesKey key;
  int spp = 0;
  double carriedShare = 0;
  std::vector<StrategyShare> carrying, ranked;  // by falling share
  std::optional<double> shareBeyondMaxBounces;
};

struct Summary {
  std::vector<ConvergenceGroup> convergence;
  std::vector<BestIntegrator> best;
  std::vector<Speedup> speedup;
  std::vector<StrategiesSummary> strategies;
  std::vector<EqualTime> equalTime;
  double confidence = 0.95;
};

Summary summarize(const SummaryRecords& records, double confidence = 0.95);
// The same of the records read from `file` (summary_records.h: a record that lacks a key the
// summary reads is an error naming `file`, the record and the key).
Summary summarize(const std::vector<nlohmann::json>& records, const std::string& file,
                  double confidence = 0.95);

// The summary as summary.json holds it for reports/make_report.py (non-finite numbers as
// null).
nlohmann::json toJson(const Summary& summary);
// The summary as text tables (what `verity study` prints and the Markdown report shows).
std::string summaryText(const Summary& summary);

}  // namespace verity::studies
