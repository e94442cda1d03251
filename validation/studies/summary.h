// Summaries of study results: log-log slopes with confidence intervals, efficiencies, the
// most efficient integrator, speed-ups. The report prints these numbers; the plots are
// drawn from the same records by reports/make_report.py.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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
nlohmann::json summarize(const SummaryRecords& records, double confidence = 0.95);
// The same of the records read from `file` (summary_records.h: a record that lacks a key the
// summary reads is an error naming `file`, the record and the key).
nlohmann::json summarize(const std::vector<nlohmann::json>& records, const std::string& file,
                         double confidence = 0.95);

// The summary as text tables (what `verity study` prints and the Markdown report shows).
std::string summaryText(const nlohmann::json& summary);

}  // namespace verity::studies
