#include "validation/studies/summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "validation/studies/fit.h"
#include "validation/studies/study_sampler.h"
#include "validation/studies/summary_records.h"

namespace verity::studies {

namespace {

double mean(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return v.empty() ? 0 : sum / double(v.size());
}

// The standard error of the mean of v (NaN below two values).
double standardError(const std::vector<double>& v) {
  if (v.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  const double m = mean(v);
  double ss = 0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / double(v.size() - 1) / double(v.size()));
}

// The wall time at which the line fitted to log mean relMSE against log mean wall time reaches
// `target`, with its inverse-prediction interval (fit.h). "reached" only where the target lies
// among the means measured: outside them the line is an extrapolation, and the report says
// "not reached" (below every mean) or "before the smallest budget" (above every mean).
TimeToAccuracy timeToAccuracy(const LineFit& fit, const std::vector<double>& meanErr,
                              double target) {
  TimeToAccuracy out;
  out.targetRelMse = target;
  if (fit.n < 3 || meanErr.empty() || !std::isfinite(fit.slope)) return out;
  const auto [lo, hi] = std::minmax_element(meanErr.begin(), meanErr.end());
  const Crossing c = crossing(fit, std::log(target));
  out.seconds = std::exp(c.x);
  out.bounded = c.bounded;
  if (c.bounded) out.secondsLow = std::exp(c.low), out.secondsHigh = std::exp(c.high);
  out.status = target < *lo   ? AccuracyStatus::NotReached
               : target > *hi ? AccuracyStatus::BeforeSmallestBudget
               : !c.bounded   ? AccuracyStatus::SlopeNotSignificant
                              : AccuracyStatus::Reached;
  return out;
}

// The summary of the runs of one convergence group at one budget.
BudgetSummary budgetSummary(double budget, const std::vector<const ConvergenceRun*>& runs) {
  std::vector<double> e, t, c, s, eff, var;
  for (const ConvergenceRun* r : runs) {
    e.push_back(r->relMse);
    t.push_back(r->wallSeconds);
    c.push_back(r->cpuSeconds);
    s.push_back(r->spp);
    if (r->relVariance) var.push_back(*r->relVariance);
    eff.push_back(1.0 / (r->relMse * r->wallSeconds));
  }
  BudgetSummary b;
  b.budget = budget;
  b.runs = runs.size();
  b.meanRelMse = mean(e);
  b.relMseStdError = standardError(e);
  b.meanWallSeconds = mean(t);
  b.wallSecondsStdError = standardError(t);
  b.meanSpp = mean(s);
  b.medianRelMse = median(e);
  b.medianRelVariance = median(var);
  b.medianWallSeconds = median(t);
  b.medianCpuSeconds = median(c);
  b.medianSpp = median(s);
  b.medianEfficiency = median(eff);
  return b;
}

// The summary of one convergence group: its fits, time to accuracy, efficiency and budgets.
ConvergenceGroup convergenceGroup(const ConvergenceGroupKey& key,
                                  const std::vector<const ConvergenceRun*>& runs,
                                  double confidence) {
  const ConvergenceRun& first = *runs.front();
  std::vector<double> time, spp, err;
  std::map<double, std::vector<const ConvergenceRun*>> byBudget;
  for (const ConvergenceRun* r : runs) {
    time.push_back(r->wallSeconds);
    spp.push_back(r->spp);
    err.push_back(r->relMse);
    byBudget[r->budget].push_back(r);
  }
  ConvergenceGroup g;
  g.key = key;
  g.runs = runs.size();
  g.relMseEpsilon = first.relMseEpsilon;
  g.referenceRelMse = first.referenceRelMse;
  g.relVarianceOmitted = !first.relVariance;
  std::vector<double> meanSpp, meanErr, meanTime;
  for (const auto& [budget, rs] : byBudget) {
    g.budgets.push_back(budgetSummary(budget, rs));
    meanSpp.push_back(g.budgets.back().meanSpp);
    meanErr.push_back(g.budgets.back().meanRelMse);
    meanTime.push_back(g.budgets.back().meanWallSeconds);
  }
  // With one budget, the spread of times is noise, not cost: no slope.
  if (byBudget.size() < 2)
    time.clear(), spp.clear(), err.clear(), meanSpp.clear(), meanTime.clear();
  g.fitTime = fitLogLog(time, err, confidence);
  g.fitSpp = fitLogLog(spp, err, confidence);
  g.fitSppOfMeans = fitLogLog(meanSpp, meanErr, confidence);
  g.fitTimeOfMeans = fitLogLog(meanTime, meanErr, confidence);
  for (double target : kAccuracyTargets)
    g.timeToAccuracy.push_back(timeToAccuracy(g.fitTimeOfMeans, meanErr, target));
  g.efficiency = g.budgets.back().medianEfficiency;
  return g;
}

// Per efficiency key: the most efficient integrator and its ratio to every other.
std::vector<BestIntegrator> bestIntegrators(
    const std::map<EfficiencyKey, std::map<std::string, double>>& efficiencies) {
  std::vector<BestIntegrator> out;
  for (const auto& [key, effs] : efficiencies) {
    BestIntegrator b;
    b.key = key;
    b.efficiency = -1;
    for (const auto& [name, e] : effs)
      if (e > b.efficiency) b.efficiency = e, b.integrator = name;
    for (const auto& [name, e] : effs) b.timesBetterThan[name] = b.efficiency / e;
    out.push_back(std::move(b));
  }
  return out;
}

// Per speed-up key and thread count: the median wall time and the speed-up over the fewest
// threads measured.
std::vector<Speedup> speedups(const std::vector<SpeedupRun>& runs) {
  struct Times {
    std::vector<double> wall, cpu;
  };
  std::map<SpeedupKey, std::map<int, Times>> byKey;
  for (const SpeedupRun& r : runs) {
    Times& t = byKey[{r.scene, r.width, r.height, r.integrator, r.maxBounces, r.spp}][r.threads];
    t.wall.push_back(r.wallSeconds);
    t.cpu.push_back(r.cpuSeconds);
  }
  std::vector<Speedup> out;
  for (const auto& [key, byThreads] : byKey) {
    const int fewest = byThreads.begin()->first;
    const double base = median(byThreads.begin()->second.wall);
    for (const auto& [threads, times] : byThreads) {
      Speedup s;
      s.key = key;
      s.threads = threads;
      s.baselineThreads = fewest;
      s.repeats = times.wall.size();
      s.medianWallSeconds = median(times.wall);
      s.speedup = base / s.medianWallSeconds;
      // CPU seconds per wall second: how many cores the render really had. On a loaded
      // machine it stays under the thread count, and so does the speed-up.
      s.coresUsed = median(times.cpu) / std::max(s.medianWallSeconds, 1e-12);
      s.parallelEfficiency = s.speedup * fewest / std::max(threads, 1);
      out.push_back(s);
    }
  }
  return out;
}

// One strategies record's strategies ranked by share, and the fewest that carry
// kCarriedShare of the image.
StrategiesSummary strategiesSummary(const StrategiesKey& key, const StrategiesRun& r) {
  StrategiesSummary out;
  out.key = key;
  out.spp = r.spp;
  out.shareBeyondMaxBounces = r.shareBeyondMaxBounces;
  out.ranked = r.strategies;
  std::stable_sort(
      out.ranked.begin(), out.ranked.end(),
      [](const StrategyShare& a, const StrategyShare& b) { return a.share > b.share; });
  for (const StrategyShare& st : out.ranked) {
    if (out.carriedShare >= kCarriedShare) break;
    out.carriedShare += st.share;
    out.carrying.push_back(st);
  }
  return out;
}

// One strategies record per scene, resolution and max bounces: the one of most samples (of
// the lowest run), whose shares are the least noisy.
std::vector<StrategiesSummary> strategiesSummaries(const std::vector<StrategiesRun>& runs) {
  std::map<StrategiesKey, const StrategiesRun*> kept;
  for (const StrategiesRun& r : runs) {
    const StrategiesRun*& k = kept[{r.scene, r.width, r.height, r.maxBounces}];
    if (!k || r.spp > k->spp || (r.spp == k->spp && r.run < k->run)) k = &r;
  }
  std::vector<StrategiesSummary> out;
  for (const auto& [key, r] : kept) out.push_back(strategiesSummary(key, *r));
  return out;
}

nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json toJson(const LineFit& f) {
  return {{"n", f.n},
          {"slope", number(f.slope)},
          {"intercept", number(f.intercept)},
          {"slope_std_error", number(f.slopeStdError)},
          {"slope_low", number(f.slopeLow)},
          {"slope_high", number(f.slopeHigh)},
          {"confidence", f.confidence},
          {"residual_std", number(f.residualStd)}};
}

nlohmann::json toJson(const TimeToAccuracy& a) {
  nlohmann::json out = {{"target_rel_mse", a.targetRelMse},
                        {"status", accuracyStatusName(a.status)}};
  if (a.status == AccuracyStatus::NoFit) return out;
  out["seconds"] = number(a.seconds);
  if (a.bounded) {
    out["seconds_low"] = number(a.secondsLow);
    out["seconds_high"] = number(a.secondsHigh);
  }
  return out;
}

nlohmann::json toJson(const BudgetSummary& b) {
  return {{"budget", b.budget},
          {"mean_rel_mse", b.meanRelMse},
          {"rel_mse_std_error", number(b.relMseStdError)},
          {"mean_wall_seconds", b.meanWallSeconds},
          {"wall_seconds_std_error", number(b.wallSecondsStdError)},
          {"mean_spp", b.meanSpp},
          {"runs", b.runs},
          {"median_rel_mse", b.medianRelMse},
          {"median_rel_variance", number(b.medianRelVariance)},
          {"median_wall_seconds", b.medianWallSeconds},
          {"median_cpu_seconds", b.medianCpuSeconds},
          {"median_spp", b.medianSpp},
          {"median_efficiency", b.medianEfficiency}};
}

nlohmann::json toJson(const ConvergenceGroup& g) {
  nlohmann::json accuracy = nlohmann::json::array(), budgets = nlohmann::json::array();
  for (const TimeToAccuracy& a : g.timeToAccuracy) accuracy.push_back(toJson(a));
  for (const BudgetSummary& b : g.budgets) budgets.push_back(toJson(b));
  nlohmann::json out = {{"scene", g.key.scene},
                        {"width", g.key.width},
                        {"height", g.key.height},
                        {"integrator", g.key.integrator},
                        {"sampler", g.key.sampler},
                        {"max_bounces", g.key.maxBounces},
                        {"threads", g.key.threads},
                        {"budget_type", budgetTypeName(g.key.budgetType)},
                        {"runs", g.runs},
                        {"rel_mse_epsilon", g.relMseEpsilon},
                        {"reference_rel_mse", g.referenceRelMse},
                        {"fit_time", toJson(g.fitTime)},
                        {"fit_spp", toJson(g.fitSpp)},
                        {"fit_spp_of_means", toJson(g.fitSppOfMeans)},
                        {"fit_time_of_means", toJson(g.fitTimeOfMeans)},
                        {"time_to_accuracy", accuracy},
                        {"efficiency", g.efficiency},
                        {"budgets", budgets}};
  if (g.relVarianceOmitted) out["rel_variance_omitted"] = kCorrelatedSamplesNote;
  return out;
}

nlohmann::json toJson(const BestIntegrator& b) {
  return {{"scene", b.key.scene},
          {"width", b.key.width},
          {"height", b.key.height},
          {"sampler", b.key.sampler},
          {"budget_type", budgetTypeName(b.key.budgetType)},
          {"threads", b.key.threads},
          {"integrator", b.integrator},
          {"efficiency", b.efficiency},
          {"times_better_than", b.timesBetterThan}};
}

nlohmann::json toJson(const EqualTime& e) {
  nlohmann::json integrators = nlohmann::json::object();
  for (const auto& [name, c] : e.integrators)
    integrators[name] = {{"mean_rel_mse", c.meanRelMse},
                         {"rel_mse_std_error", number(c.relMseStdError)},
                         {"mean_spp", c.meanSpp},
                         {"runs", c.runs}};
  return {{"scene", e.key.scene},      {"width", e.key.width},     {"height", e.key.height},
          {"sampler", e.key.sampler},  {"threads", e.key.threads}, {"seconds", e.key.seconds},
          {"integrators", integrators}};
}

nlohmann::json toJson(const Speedup& s) {
  return {{"scene", s.key.scene},
          {"width", s.key.width},
          {"height", s.key.height},
          {"integrator", s.key.integrator},
          {"max_bounces", s.key.maxBounces},
          {"spp", s.key.spp},
          {"threads", s.threads},
          {"baseline_threads", s.baselineThreads},
          {"repeats", s.repeats},
          {"median_wall_seconds", s.medianWallSeconds},
          {"speedup", s.speedup},
          {"cores_used", s.coresUsed},
          {"parallel_efficiency", s.parallelEfficiency}};
}

nlohmann::json toJson(const StrategiesSummary& s) {
  // The strategies as their records hold them, every field.
  nlohmann::json carrying = nlohmann::json::array(), ranked = nlohmann::json::array();
  for (const StrategyShare& st : s.carrying) carrying.push_back(st.fields);
  for (const StrategyShare& st : s.ranked) ranked.push_back(st.fields);
  nlohmann::json out = {{"scene", s.key.scene},
                        {"width", s.key.width},
                        {"height", s.key.height},
                        {"max_bounces", s.key.maxBounces},
                        {"spp", s.spp},
                        {"carried_share_target", kCarriedShare},
                        {"carried_share", s.carriedShare},
                        {"carrying", carrying},
                        {"ranked", ranked}};
  if (s.shareBeyondMaxBounces) out["share_beyond_max_bounces"] = *s.shareBeyondMaxBounces;
  return out;
}

template <typename T>
nlohmann::json toJsonArray(const std::vector<T>& items) {
  nlohmann::json out = nlohmann::json::array();
  for (const T& item : items) out.push_back(toJson(item));
  return out;
}

std::string fitText(const LineFit& f) {
  if (!std::isfinite(f.slope)) return "n/a";
  if (!std::isfinite(f.slopeLow)) return fmt::format("{:.3f}", f.slope);
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]", f.slope, f.slopeLow, f.slopeHigh);
}

std::string accuracyText(const TimeToAccuracy& a) {
  if (a.status == AccuracyStatus::Reached)
    return fmt::format("{:.3g} s [{:.3g}, {:.3g}]", a.seconds, a.secondsLow, a.secondsHigh);
  return accuracyStatusName(a.status);
}

}  // namespace

const char* accuracyStatusName(AccuracyStatus status) {
  switch (status) {
    case AccuracyStatus::NoFit:
      return "no fit";
    case AccuracyStatus::Reached:
      return "reached";
    case AccuracyStatus::NotReached:
      return "not reached";
    case AccuracyStatus::BeforeSmallestBudget:
      return "before the smallest budget";
    case AccuracyStatus::SlopeNotSignificant:
      return "slope not significant";
  }
  return "";
}

Summary summarize(const SummaryRecords& records, double confidence) {
  Summary summary;
  summary.confidence = confidence;
  std::map<ConvergenceGroupKey, std::vector<const ConvergenceRun*>> groups;
  for (const ConvergenceRun& r : records.convergence)
    groups[{r.scene, r.width, r.height, r.integrator, r.sampler, r.maxBounces, r.threads,
            r.budgetType}]
        .push_back(&r);
  std::map<EfficiencyKey, std::map<std::string, double>> efficiencies;
  std::map<EqualTimeKey, std::map<std::string, EqualTimeCell>> equalTime;
  for (const auto& [key, runs] : groups) {
    ConvergenceGroup g = convergenceGroup(key, runs, confidence);
    efficiencies[{key.scene, key.width, key.height, key.sampler, key.budgetType, key.threads}]
                [key.integrator] = g.efficiency;
    if (key.budgetType == BudgetType::Time)
      for (const BudgetSummary& b : g.budgets)
        equalTime[{key.scene, key.width, key.height, key.sampler, key.threads, b.budget}]
                 [key.integrator] = {b.meanRelMse, b.relMseStdError, b.meanSpp, b.runs};
    summary.convergence.push_back(std::move(g));
  }
  summary.best = bestIntegrators(efficiencies);
  summary.speedup = speedups(records.speedup);
  summary.strategies = strategiesSummaries(records.strategies);
  for (auto& [key, integrators] : equalTime)
    summary.equalTime.push_back({key, std::move(integrators)});
  return summary;
}

Summary summarize(const std::vector<nlohmann::json>& records, const std::string& file,
                  double confidence) {
  SummaryRecords typed;
  addSummaryRecords(records, file, typed);
  return summarize(typed, confidence);
}

nlohmann::json toJson(const Summary& summary) {
  return {{"convergence", toJsonArray(summary.convergence)},
          {"best", toJsonArray(summary.best)},
          {"speedup", toJsonArray(summary.speedup)},
          {"strategies", toJsonArray(summary.strategies)},
          {"equal_time", toJsonArray(summary.equalTime)},
          {"confidence", summary.confidence}};
}

std::string summaryText(const Summary& summary) {
  const int percent = int(std::lround(100 * summary.confidence));
  std::string s;
  if (!summary.convergence.empty()) {
    s += fmt::format(
        "Convergence ({}% confidence intervals of the log-log slopes; relMSE epsilon {})\n",
        percent, summary.convergence[0].relMseEpsilon);
    s += fmt::format("{:<18} {:<16} {:<11} {:>7} {:>5} {:>28} {:>28} {:>11}\n", "scene",
                     "integrator", "sampler", "threads", "runs", "slope vs time", "slope vs spp",
                     "efficiency");
    for (const ConvergenceGroup& g : summary.convergence)
      s += fmt::format("{:<18} {:<16} {:<11} {:>7} {:>5} {:>28} {:>28} {:>11.4g}\n", g.key.scene,
                       g.key.integrator, g.key.sampler, g.key.threads, g.runs, fitText(g.fitTime),
                       fitText(g.fitSpp), g.efficiency);
    std::set<std::string> omitted;
    for (const ConvergenceGroup& g : summary.convergence)
      if (g.relVarianceOmitted) omitted.insert(g.key.sampler);
    for (const std::string& sampler : omitted)
      s += fmt::format("no rel_variance for the {} sampler: {}\n", sampler, kCorrelatedSamplesNote);
    s += fmt::format("Time to accuracy (wall seconds to reach the relative MSE, {}% interval)\n",
                     percent);
  }
  for (const ConvergenceGroup& g : summary.convergence) {
    std::string cells;
    for (const TimeToAccuracy& a : g.timeToAccuracy)
      cells += fmt::format("  {:g}: {}", a.targetRelMse, accuracyText(a));
    s += fmt::format("{:<18} {:<16} {:<11} {:>2} threads {}\n", g.key.scene, g.key.integrator,
                     g.key.sampler, g.key.threads, cells);
  }
  for (const EqualTime& e : summary.equalTime) {
    std::string cells;
    for (const auto& [name, c] : e.integrators)
      cells += fmt::format("{}{} {:.4g}", cells.empty() ? "" : ", ", name, c.meanRelMse);
    s += fmt::format("equal time on {} ({} sampler, {} threads, {:g} s): relMSE {}\n", e.key.scene,
                     e.key.sampler, e.key.threads, e.key.seconds, cells);
  }
  for (const BestIntegrator& b : summary.best) {
    s += fmt::format("most efficient on {} ({} sampler, {} threads, {} budgets): {}", b.key.scene,
                     b.key.sampler, b.key.threads, budgetTypeName(b.key.budgetType), b.integrator);
    std::string others;
    for (const auto& [name, ratio] : b.timesBetterThan)
      if (name != b.integrator)
        others += fmt::format("{}{:.2f}x {}", others.empty() ? "" : ", ", ratio, name);
    s += others.empty() ? "\n" : fmt::format("; its efficiency is {}\n", others);
  }
  if (!summary.speedup.empty()) {
    s += "Speed-up (medians of alternating repeats)\n";
    s +=
        fmt::format("{:<18} {:<16} {:>7} {:>8} {:>12} {:>9} {:>11} {:>11}\n", "scene", "integrator",
                    "threads", "repeats", "median s", "speed-up", "par. eff.", "cores used");
    for (const Speedup& g : summary.speedup)
      s += fmt::format("{:<18} {:<16} {:>7} {:>8} {:>12.4f} {:>9.3f} {:>11.3f} {:>11.2f}\n",
                       g.key.scene, g.key.integrator, g.threads, g.repeats, g.medianWallSeconds,
                       g.speedup, g.parallelEfficiency, g.coresUsed);
  }
  for (const StrategiesSummary& g : summary.strategies) {
    std::string list;
    for (const StrategyShare& st : g.carrying)
      list += fmt::format("{}(s={}, t={}) {:.1f}%", list.empty() ? "" : ", ", st.s, st.t,
                          100 * st.share);
    s += fmt::format("BDPT strategies carrying {:.0f}% of {} ({} spp, max bounces {}): {}\n",
                     100 * g.carriedShare, g.key.scene, g.spp, g.key.maxBounces, list);
  }
  return s;
}

}  // namespace verity::studies
