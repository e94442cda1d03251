#include "validation/studies/summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "validation/studies/fit.h"
#include "validation/studies/study_sampler.h"
#include "validation/studies/summary_records.h"

namespace verity::studies {

namespace {

nlohmann::json fitJson(const LineFit& f) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  return {{"n", f.n},
          {"slope", num(f.slope)},
          {"intercept", num(f.intercept)},
          {"slope_std_error", num(f.slopeStdError)},
          {"slope_low", num(f.slopeLow)},
          {"slope_high", num(f.slopeHigh)},
          {"confidence", f.confidence},
          {"residual_std", num(f.residualStd)}};
}

std::string fmtFit(const nlohmann::json& f) {
  if (f["slope"].is_null()) return "n/a";
  if (f["slope_low"].is_null()) return fmt::format("{:.3f}", f["slope"].get<double>());
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]", f["slope"].get<double>(),
                     f["slope_low"].get<double>(), f["slope_high"].get<double>());
}

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

nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

// The wall time at which the line fitted to log mean relMSE against log mean wall time reaches
// `target`, with its inverse-prediction interval (fit.h). "reached" only where the target lies
// among the means measured: outside them the line is an extrapolation, and the report says
// "not reached" (below every mean) or "before the smallest budget" (above every mean).
nlohmann::json timeToAccuracy(const LineFit& fit, const std::vector<double>& meanErr,
                              double target) {
  nlohmann::json out = {{"target_rel_mse", target}};
  const auto [lo, hi] = std::minmax_element(meanErr.begin(), meanErr.end());
  if (fit.n < 3 || meanErr.empty() || !std::isfinite(fit.slope)) {
    out["status"] = "no fit";
    return out;
  }
  const Crossing c = crossing(fit, std::log(target));
  out["seconds"] = number(std::exp(c.x));
  if (c.bounded) {
    out["seconds_low"] = number(std::exp(c.low));
    out["seconds_high"] = number(std::exp(c.high));
  }
  out["status"] = target < *lo   ? "not reached"
                  : target > *hi ? "before the smallest budget"
                  : !c.bounded   ? "slope not significant"
                                 : "reached";
  return out;
}

std::string accuracyText(const nlohmann::json& a) {
  const std::string status = a["status"].get<std::string>();
  if (status == "reached")
    return fmt::format("{:.3g} s [{:.3g}, {:.3g}]", a["seconds"].get<double>(),
                       a["seconds_low"].get<double>(), a["seconds_high"].get<double>());
  return status;
}

// The efficiencies of the convergence groups: (scene, w, h, sampler, budget type, threads) ->
// integrator -> efficiency.
using EfficiencyKey = std::tuple<std::string, int, int, std::string, std::string, int>;
using Efficiencies = std::map<EfficiencyKey, std::map<std::string, double>>;
// The time budgets of the convergence groups: (scene, w, h, sampler, threads, seconds) ->
// integrator -> that budget's summary.
using EqualTimeKey = std::tuple<std::string, int, int, std::string, int, double>;
using EqualTimes = std::map<EqualTimeKey, nlohmann::json>;

// The summary of the runs of one convergence group at one budget.
nlohmann::json budgetSummary(double budget, const std::vector<const ConvergenceRun*>& runs) {
  std::vector<double> e, t, c, s, eff, var;
  for (const ConvergenceRun* r : runs) {
    e.push_back(r->relMse);
    t.push_back(r->wallSeconds);
    c.push_back(r->cpuSeconds);
    s.push_back(r->spp);
    if (r->relVariance) var.push_back(*r->relVariance);
    eff.push_back(1.0 / (r->relMse * r->wallSeconds));
  }
  return {{"budget", budget},
          {"mean_rel_mse", mean(e)},
          {"rel_mse_std_error", number(standardError(e))},
          {"mean_wall_seconds", mean(t)},
          {"wall_seconds_std_error", number(standardError(t))},
          {"mean_spp", mean(s)},
          {"runs", runs.size()},
          {"median_rel_mse", median(e)},
          {"median_rel_variance", number(median(var))},
          {"median_wall_seconds", median(t)},
          {"median_cpu_seconds", median(c)},
          {"median_spp", median(s)},
          {"median_efficiency", median(eff)}};
}

// The summary of one convergence group (runs of one scene, resolution, integrator, sampler,
// max bounces, threads and budget type): its fits, time to accuracy, efficiency and budgets.
nlohmann::json convergenceGroup(const std::vector<const ConvergenceRun*>& runs, double confidence) {
  const ConvergenceRun& first = *runs.front();
  std::vector<double> time, spp, err;
  std::map<double, std::vector<const ConvergenceRun*>> byBudget;
  for (const ConvergenceRun* r : runs) {
    time.push_back(r->wallSeconds);
    spp.push_back(r->spp);
    err.push_back(r->relMse);
    byBudget[r->budget].push_back(r);
  }
  nlohmann::json budgets = nlohmann::json::array();
  std::vector<double> meanSpp, meanErr, meanTime;
  for (const auto& [budget, rs] : byBudget) {
    budgets.push_back(budgetSummary(budget, rs));
    meanSpp.push_back(budgets.back()["mean_spp"].get<double>());
    meanErr.push_back(budgets.back()["mean_rel_mse"].get<double>());
    meanTime.push_back(budgets.back()["mean_wall_seconds"].get<double>());
  }
  // With one budget, the spread of times is noise, not cost: no slope.
  if (byBudget.size() < 2)
    time.clear(), spp.clear(), err.clear(), meanSpp.clear(), meanTime.clear();
  const LineFit timeOfMeans = fitLogLog(meanTime, meanErr, confidence);
  nlohmann::json accuracy = nlohmann::json::array();
  for (double target : kAccuracyTargets)
    accuracy.push_back(timeToAccuracy(timeOfMeans, meanErr, target));
  nlohmann::json group = {{"scene", first.scene},
                          {"width", first.width},
                          {"height", first.height},
                          {"integrator", first.integrator},
                          {"sampler", first.sampler},
                          {"max_bounces", first.maxBounces},
                          {"threads", first.threads},
                          {"budget_type", first.budgetType},
                          {"runs", runs.size()},
                          {"rel_mse_epsilon", first.relMseEpsilon},
                          {"reference_rel_mse", first.referenceRelMse},
                          {"fit_time", fitJson(fitLogLog(time, err, confidence))},
                          {"fit_spp", fitJson(fitLogLog(spp, err, confidence))},
                          {"fit_spp_of_means", fitJson(fitLogLog(meanSpp, meanErr, confidence))},
                          {"fit_time_of_means", fitJson(timeOfMeans)},
                          {"time_to_accuracy", accuracy},
                          {"efficiency", budgets.back()["median_efficiency"].get<double>()},
                          {"budgets", budgets}};
  if (!first.relVariance) group["rel_variance_omitted"] = kCorrelatedSamplesNote;
  return group;
}

// The convergence runs grouped by (scene, resolution, integrator, sampler, max bounces,
// threads, budget type), in the order of those keys.
std::vector<std::vector<const ConvergenceRun*>> convergenceGroups(
    const std::vector<ConvergenceRun>& runs) {
  using GroupKey =
      std::tuple<std::string, int, int, std::string, std::string, int, int, std::string>;
  std::map<GroupKey, std::vector<const ConvergenceRun*>> groups;
  for (const ConvergenceRun& r : runs)
    groups[{r.scene, r.width, r.height, r.integrator, r.sampler, r.maxBounces, r.threads,
            r.budgetType}]
        .push_back(&r);
  std::vector<std::vector<const ConvergenceRun*>> out;
  for (auto& [key, members] : groups) out.push_back(std::move(members));
  return out;
}

// Per (scene, resolution, sampler, budget type, threads): the most efficient integrator and
// its ratio to every other.
nlohmann::json bestEntries(const Efficiencies& efficiencies) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [key, effs] : efficiencies) {
    const auto& [scene, w, h, sampler, budgetType, threads] = key;
    std::string best;
    double bestEff = -1;
    for (const auto& [name, e] : effs)
      if (e > bestEff) bestEff = e, best = name;
    nlohmann::json ratios = nlohmann::json::object();
    for (const auto& [name, e] : effs) ratios[name] = bestEff / e;
    out.push_back({{"scene", scene},
                   {"width", w},
                   {"height", h},
                   {"sampler", sampler},
                   {"budget_type", budgetType},
                   {"threads", threads},
                   {"integrator", best},
                   {"efficiency", bestEff},
                   {"times_better_than", ratios}});
  }
  return out;
}

nlohmann::json equalTimeEntries(const EqualTimes& equalTime) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [key, byIntegrator] : equalTime) {
    const auto& [scene, w, h, sampler, threads, seconds] = key;
    out.push_back({{"scene", scene},
                   {"width", w},
                   {"height", h},
                   {"sampler", sampler},
                   {"threads", threads},
                   {"seconds", seconds},
                   {"integrators", byIntegrator}});
  }
  return out;
}

// Per (scene, resolution, integrator, max bounces, spp) and thread count: the median wall time
// and the speed-up over the fewest threads measured.
nlohmann::json speedupEntries(const std::vector<SpeedupRun>& runs) {
  using SpeedKey = std::tuple<std::string, int, int, std::string, int, int>;
  std::map<SpeedKey, std::map<int, std::vector<double>>> speed, speedCpu;
  for (const SpeedupRun& r : runs) {
    const SpeedKey key{r.scene, r.width, r.height, r.integrator, r.maxBounces, r.spp};
    speed[key][r.threads].push_back(r.wallSeconds);
    speedCpu[key][r.threads].push_back(r.cpuSeconds);
  }
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [key, byThreads] : speed) {
    const auto& [scene, w, h, integrator, maxBounces, spp] = key;
    const int fewest = byThreads.begin()->first;
    const double base = median(byThreads.begin()->second);
    for (const auto& [threads, times] : byThreads) {
      const double m = median(times);
      const double s = base / m;
      // CPU seconds per wall second: how many cores the render really had. On a loaded
      // machine it stays under the thread count, and so does the speed-up.
      const double coresUsed = median(speedCpu[key][threads]) / std::max(m, 1e-12);
      out.push_back({{"scene", scene},
                     {"width", w},
                     {"height", h},
                     {"integrator", integrator},
                     {"max_bounces", maxBounces},
                     {"spp", spp},
                     {"threads", threads},
                     {"baseline_threads", fewest},
                     {"repeats", times.size()},
                     {"median_wall_seconds", m},
                     {"speedup", s},
                     {"cores_used", coresUsed},
                     {"parallel_efficiency", s * fewest / std::max(threads, 1)}});
    }
  }
  return out;
}

// One strategies record's strategies ranked by share, and the fewest that carry
// kCarriedShare of the image.
nlohmann::json strategiesEntry(const StrategiesRun& r) {
  std::vector<const StrategyShare*> ranked;
  for (const StrategyShare& st : r.strategies) ranked.push_back(&st);
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto* a, const auto* b) { return a->share > b->share; });
  nlohmann::json carrying = nlohmann::json::array(), rankedFields = nlohmann::json::array();
  double carried = 0;
  for (const StrategyShare* st : ranked) {
    rankedFields.push_back(st->fields);
    if (carried >= kCarriedShare) continue;
    carried += st->share;
    carrying.push_back(st->fields);
  }
  nlohmann::json entry = {{"scene", r.scene},
                          {"width", r.width},
                          {"height", r.height},
                          {"max_bounces", r.maxBounces},
                          {"spp", r.spp},
                          {"carried_share_target", kCarriedShare},
                          {"carried_share", carried},
                          {"carrying", carrying},
                          {"ranked", rankedFields}};
  if (r.shareBeyondMaxBounces) entry["share_beyond_max_bounces"] = *r.shareBeyondMaxBounces;
  return entry;
}

// One strategies record per scene, resolution and max bounces: the one of most samples (of
// the lowest run), whose shares are the least noisy.
nlohmann::json strategiesEntries(const std::vector<StrategiesRun>& runs) {
  std::map<std::string, const StrategiesRun*> kept;
  for (const StrategiesRun& r : runs) {
    const std::string key = fmt::format("{}|{}x{}|{}", r.scene, r.width, r.height, r.maxBounces);
    const StrategiesRun*& k = kept[key];
    if (!k || r.spp > k->spp || (r.spp == k->spp && r.run < k->run)) k = &r;
  }
  nlohmann::json out = nlohmann::json::array();
  for (const auto& [key, r] : kept) out.push_back(strategiesEntry(*r));
  return out;
}

}  // namespace

nlohmann::json summarize(const SummaryRecords& records, double confidence) {
  nlohmann::json convergence = nlohmann::json::array();
  Efficiencies efficiencies;
  EqualTimes equalTime;
  for (const std::vector<const ConvergenceRun*>& runs : convergenceGroups(records.convergence)) {
    nlohmann::json g = convergenceGroup(runs, confidence);
    const ConvergenceRun& r = *runs.front();
    efficiencies[{r.scene, r.width, r.height, r.sampler, r.budgetType, r.threads}][r.integrator] =
        g["efficiency"].get<double>();
    if (r.budgetType == "time")
      for (const nlohmann::json& b : g["budgets"])
        equalTime[{r.scene, r.width, r.height, r.sampler, r.threads, b["budget"].get<double>()}]
                 [r.integrator] = {{"mean_rel_mse", b["mean_rel_mse"]},
                                   {"rel_mse_std_error", b["rel_mse_std_error"]},
                                   {"mean_spp", b["mean_spp"]},
                                   {"runs", b["runs"]}};
    convergence.push_back(std::move(g));
  }
  return {{"convergence", convergence},
          {"best", bestEntries(efficiencies)},
          {"speedup", speedupEntries(records.speedup)},
          {"strategies", strategiesEntries(records.strategies)},
          {"equal_time", equalTimeEntries(equalTime)},
          {"confidence", confidence}};
}

nlohmann::json summarize(const std::vector<nlohmann::json>& records, const std::string& file,
                         double confidence) {
  SummaryRecords typed;
  addSummaryRecords(records, file, typed);
  return summarize(typed, confidence);
}

std::string summaryText(const nlohmann::json& summary) {
  std::string s;
  if (!summary["convergence"].empty()) {
    s += fmt::format(
        "Convergence ({}% confidence intervals of the log-log slopes; relMSE epsilon {})\n",
        int(std::lround(100 * summary["confidence"].get<double>())),
        summary["convergence"][0]["rel_mse_epsilon"].get<double>());
    s += fmt::format("{:<18} {:<16} {:<11} {:>7} {:>5} {:>28} {:>28} {:>11}\n", "scene",
                     "integrator", "sampler", "threads", "runs", "slope vs time", "slope vs spp",
                     "efficiency");
    for (const nlohmann::json& g : summary["convergence"])
      s += fmt::format("{:<18} {:<16} {:<11} {:>7} {:>5} {:>28} {:>28} {:>11.4g}\n",
                       g["scene"].get<std::string>(), g["integrator"].get<std::string>(),
                       g["sampler"].get<std::string>(), g["threads"].get<int>(),
                       g["runs"].get<size_t>(), fmtFit(g["fit_time"]), fmtFit(g["fit_spp"]),
                       g["efficiency"].get<double>());
    std::set<std::string> omitted;
    for (const nlohmann::json& g : summary["convergence"])
      if (g.contains("rel_variance_omitted")) omitted.insert(g["sampler"].get<std::string>());
    for (const std::string& sampler : omitted)
      s += fmt::format("no rel_variance for the {} sampler: {}\n", sampler, kCorrelatedSamplesNote);
  }
  bool accuracyHeader = false;
  for (const nlohmann::json& g : summary["convergence"]) {
    if (!g.contains("time_to_accuracy")) continue;
    if (!accuracyHeader) {
      s += fmt::format("Time to accuracy (wall seconds to reach the relative MSE, {}% interval)\n",
                       int(std::lround(100 * summary["confidence"].get<double>())));
      accuracyHeader = true;
    }
    std::string cells;
    for (const nlohmann::json& a : g["time_to_accuracy"])
      cells += fmt::format("  {:g}: {}", a["target_rel_mse"].get<double>(), accuracyText(a));
    s += fmt::format("{:<18} {:<16} {:<11} {:>2} threads {}\n", g["scene"].get<std::string>(),
                     g["integrator"].get<std::string>(), g["sampler"].get<std::string>(),
                     g["threads"].get<int>(), cells);
  }
  for (const nlohmann::json& e : summary.value("equal_time", nlohmann::json::array())) {
    std::string cells;
    for (const auto& [name, v] : e["integrators"].items())
      cells += fmt::format("{}{} {:.4g}", cells.empty() ? "" : ", ", name,
                           v["mean_rel_mse"].get<double>());
    s += fmt::format("equal time on {} ({} sampler, {} threads, {:g} s): relMSE {}\n",
                     e["scene"].get<std::string>(), e["sampler"].get<std::string>(),
                     e["threads"].get<int>(), e["seconds"].get<double>(), cells);
  }
  for (const nlohmann::json& b : summary["best"]) {
    s += fmt::format("most efficient on {} ({} sampler, {} threads, {} budgets): {}",
                     b["scene"].get<std::string>(), b["sampler"].get<std::string>(),
                     b["threads"].get<int>(), b["budget_type"].get<std::string>(),
                     b["integrator"].get<std::string>());
    std::string others;
    for (const auto& [name, ratio] : b["times_better_than"].items())
      if (name != b["integrator"].get<std::string>())
        others +=
            fmt::format("{}{:.2f}x {}", others.empty() ? "" : ", ", ratio.get<double>(), name);
    s += others.empty() ? "\n" : fmt::format("; its efficiency is {}\n", others);
  }
  if (!summary["speedup"].empty()) {
    s += "Speed-up (medians of alternating repeats)\n";
    s +=
        fmt::format("{:<18} {:<16} {:>7} {:>8} {:>12} {:>9} {:>11} {:>11}\n", "scene", "integrator",
                    "threads", "repeats", "median s", "speed-up", "par. eff.", "cores used");
    for (const nlohmann::json& g : summary["speedup"])
      s += fmt::format("{:<18} {:<16} {:>7} {:>8} {:>12.4f} {:>9.3f} {:>11.3f} {:>11.2f}\n",
                       g["scene"].get<std::string>(), g["integrator"].get<std::string>(),
                       g["threads"].get<int>(), g["repeats"].get<size_t>(),
                       g["median_wall_seconds"].get<double>(), g["speedup"].get<double>(),
                       g["parallel_efficiency"].get<double>(), g["cores_used"].get<double>());
  }
  for (const nlohmann::json& g : summary["strategies"]) {
    std::string list;
    for (const nlohmann::json& st : g["carrying"])
      list += fmt::format("{}(s={}, t={}) {:.1f}%", list.empty() ? "" : ", ", st["s"].get<int>(),
                          st["t"].get<int>(), 100 * st["share"].get<double>());
    s += fmt::format("BDPT strategies carrying {:.0f}% of {} ({} spp, max bounces {}): {}\n",
                     100 * g["carried_share"].get<double>(), g["scene"].get<std::string>(),
                     g["spp"].get<int>(), g["max_bounces"].get<int>(), list);
  }
  return s;
}

}  // namespace verity::studies
