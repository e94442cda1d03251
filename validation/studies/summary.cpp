#include "validation/studies/summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "validation/studies/fit.h"

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

}  // namespace

nlohmann::json summarize(const std::vector<nlohmann::json>& records, double confidence) {
  using GroupKey = std::tuple<std::string, int, int, std::string, int, int, std::string>;
  std::map<GroupKey, std::vector<const nlohmann::json*>> groups;
  using SpeedKey = std::tuple<std::string, int, int, std::string, int, int>;
  std::map<SpeedKey, std::map<int, std::vector<double>>> speed, speedCpu;
  for (const nlohmann::json& r : records) {
    const std::string study = r.value("study", "");
    if (study == "convergence")
      groups[{r.value("scene", ""), r.value("width", 0), r.value("height", 0),
              r.value("integrator", ""), r.value("max_bounces", 0), r.value("threads", 0),
              r.value("budget_type", "")}]
          .push_back(&r);
    else if (study == "speedup") {
      const SpeedKey key{r.value("scene", ""),      r.value("width", 0),       r.value("height", 0),
                         r.value("integrator", ""), r.value("max_bounces", 0), r.value("spp", 0)};
      speed[key][r.value("threads", 0)].push_back(r.value("wall_seconds", 0.0));
      speedCpu[key][r.value("threads", 0)].push_back(r.value("cpu_seconds", 0.0));
    }
  }

  nlohmann::json out = {
      {"convergence", nlohmann::json::array()}, {"best", nlohmann::json::array()},
      {"speedup", nlohmann::json::array()},     {"strategies", nlohmann::json::array()},
      {"equal_time", nlohmann::json::array()},  {"confidence", confidence}};
  // (scene, w, h, threads, seconds) -> integrator -> that budget's summary
  std::map<std::tuple<std::string, int, int, int, double>, nlohmann::json> equalTime;
  // (scene, w, h, budget type, threads) -> integrator -> efficiency
  std::map<std::tuple<std::string, int, int, std::string, int>, std::map<std::string, double>>
      efficiencies;
  for (const auto& [key, runs] : groups) {
    const auto& [scene, w, h, integrator, maxBounces, threads, budgetType] = key;
    std::vector<double> time, spp, err;
    std::map<double, std::vector<const nlohmann::json*>> byBudget;
    for (const nlohmann::json* r : runs) {
      time.push_back(r->value("wall_seconds", 0.0));
      spp.push_back(r->value("spp", 0));
      err.push_back(r->value("rel_mse", 0.0));
      byBudget[r->value("budget", 0.0)].push_back(r);
    }
    nlohmann::json budgets = nlohmann::json::array();
    std::vector<double> meanSpp, meanErr, meanTime;
    for (const auto& [budget, rs] : byBudget) {
      std::vector<double> e, t, c, s, eff, var;
      for (const nlohmann::json* r : rs) {
        e.push_back(r->value("rel_mse", 0.0));
        t.push_back(r->value("wall_seconds", 0.0));
        c.push_back(r->value("cpu_seconds", 0.0));
        s.push_back(r->value("spp", 0));
        var.push_back(r->value("rel_variance", 0.0));
        eff.push_back(1.0 / (r->value("rel_mse", 0.0) * r->value("wall_seconds", 0.0)));
      }
      meanSpp.push_back(mean(s));
      meanErr.push_back(mean(e));
      meanTime.push_back(mean(t));
      budgets.push_back({{"budget", budget},
                         {"mean_rel_mse", mean(e)},
                         {"rel_mse_std_error", number(standardError(e))},
                         {"mean_wall_seconds", mean(t)},
                         {"wall_seconds_std_error", number(standardError(t))},
                         {"mean_spp", mean(s)},
                         {"runs", rs.size()},
                         {"median_rel_mse", median(e)},
                         {"median_rel_variance", median(var)},
                         {"median_wall_seconds", median(t)},
                         {"median_cpu_seconds", median(c)},
                         {"median_spp", median(s)},
                         {"median_efficiency", median(eff)}});
    }
    const double efficiency = budgets.back()["median_efficiency"].get<double>();
    // With one budget, the spread of times is noise, not cost: no slope.
    if (byBudget.size() < 2)
      time.clear(), spp.clear(), err.clear(), meanSpp.clear(), meanTime.clear();
    const LineFit timeOfMeans = fitLogLog(meanTime, meanErr, confidence);
    nlohmann::json accuracy = nlohmann::json::array();
    for (double target : kAccuracyTargets)
      accuracy.push_back(timeToAccuracy(timeOfMeans, meanErr, target));
    efficiencies[{scene, w, h, budgetType, threads}][integrator] = efficiency;
    if (budgetType == "time")
      for (const nlohmann::json& b : budgets)
        equalTime[{scene, w, h, threads, b["budget"].get<double>()}][integrator] = {
            {"mean_rel_mse", b["mean_rel_mse"]},
            {"rel_mse_std_error", b["rel_mse_std_error"]},
            {"mean_spp", b["mean_spp"]},
            {"runs", b["runs"]}};
    const nlohmann::json* first = runs.front();
    out["convergence"].push_back(
        {{"scene", scene},
         {"width", w},
         {"height", h},
         {"integrator", integrator},
         {"max_bounces", maxBounces},
         {"threads", threads},
         {"budget_type", budgetType},
         {"runs", runs.size()},
         {"rel_mse_epsilon", first->value("rel_mse_epsilon", 0.0)},
         {"reference_rel_mse", first->value("reference_rel_mse", 0.0)},
         {"fit_time", fitJson(fitLogLog(time, err, confidence))},
         {"fit_spp", fitJson(fitLogLog(spp, err, confidence))},
         {"fit_spp_of_means", fitJson(fitLogLog(meanSpp, meanErr, confidence))},
         {"fit_time_of_means", fitJson(timeOfMeans)},
         {"time_to_accuracy", accuracy},
         {"efficiency", efficiency},
         {"budgets", budgets}});
  }
  for (const auto& [key, effs] : efficiencies) {
    const auto& [scene, w, h, budgetType, threads] = key;
    std::string best;
    double bestEff = -1;
    for (const auto& [name, e] : effs)
      if (e > bestEff) bestEff = e, best = name;
    nlohmann::json ratios = nlohmann::json::object();
    for (const auto& [name, e] : effs) ratios[name] = bestEff / e;
    out["best"].push_back({{"scene", scene},
                           {"width", w},
                           {"height", h},
                           {"budget_type", budgetType},
                           {"threads", threads},
                           {"integrator", best},
                           {"efficiency", bestEff},
                           {"times_better_than", ratios}});
  }
  for (const auto& [key, byIntegrator] : equalTime) {
    const auto& [scene, w, h, threads, seconds] = key;
    out["equal_time"].push_back({{"scene", scene},
                                 {"width", w},
                                 {"height", h},
                                 {"threads", threads},
                                 {"seconds", seconds},
                                 {"integrators", byIntegrator}});
  }
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
      out["speedup"].push_back({{"scene", scene},
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
  // One strategies record per scene, resolution and max bounces: the one of most samples
  // (of the lowest run), whose shares are the least noisy.
  std::map<std::string, const nlohmann::json*> shareRecords;
  for (const nlohmann::json& r : records) {
    if (r.value("study", "") != "strategies" || !r.contains("strategies")) continue;
    const std::string key = fmt::format("{}|{}x{}|{}", r.value("scene", ""), r.value("width", 0),
                                        r.value("height", 0), r.value("max_bounces", 0));
    const nlohmann::json*& kept = shareRecords[key];
    if (!kept || r.value("spp", 0) > kept->value("spp", 0) ||
        (r.value("spp", 0) == kept->value("spp", 0) && r.value("run", 0) < kept->value("run", 0)))
      kept = &r;
  }
  for (const auto& [key, record] : shareRecords) {
    const nlohmann::json& r = *record;
    std::vector<nlohmann::json> ranked(r["strategies"].begin(), r["strategies"].end());
    std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
      return a.value("share", 0.0) > b.value("share", 0.0);
    });
    // The fewest strategies that together make kCarriedShare of the image carry it.
    nlohmann::json carrying = nlohmann::json::array();
    double carried = 0;
    for (const nlohmann::json& st : ranked) {
      if (carried >= kCarriedShare) break;
      carried += st.value("share", 0.0);
      carrying.push_back(st);
    }
    nlohmann::json entry = {{"scene", r.value("scene", "")},
                            {"width", r.value("width", 0)},
                            {"height", r.value("height", 0)},
                            {"max_bounces", r.value("max_bounces", 0)},
                            {"spp", r.value("spp", 0)},
                            {"carried_share_target", kCarriedShare},
                            {"carried_share", carried},
                            {"carrying", carrying},
                            {"ranked", ranked}};
    if (r.contains("share_beyond_max_bounces"))
      entry["share_beyond_max_bounces"] = r["share_beyond_max_bounces"];
    out["strategies"].push_back(entry);
  }
  return out;
}

std::string summaryText(const nlohmann::json& summary) {
  std::string s;
  if (!summary["convergence"].empty()) {
    s += fmt::format(
        "Convergence ({}% confidence intervals of the log-log slopes; relMSE epsilon {})\n",
        int(std::lround(100 * summary["confidence"].get<double>())),
        summary["convergence"][0]["rel_mse_epsilon"].get<double>());
    s += fmt::format("{:<18} {:<16} {:>7} {:>5} {:>28} {:>28} {:>11}\n", "scene", "integrator",
                     "threads", "runs", "slope vs time", "slope vs spp", "efficiency");
    for (const nlohmann::json& g : summary["convergence"])
      s += fmt::format("{:<18} {:<16} {:>7} {:>5} {:>28} {:>28} {:>11.4g}\n",
                       g["scene"].get<std::string>(), g["integrator"].get<std::string>(),
                       g["threads"].get<int>(), g["runs"].get<size_t>(), fmtFit(g["fit_time"]),
                       fmtFit(g["fit_spp"]), g["efficiency"].get<double>());
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
    s += fmt::format("{:<18} {:<16} {:>2} threads {}\n", g["scene"].get<std::string>(),
                     g["integrator"].get<std::string>(), g["threads"].get<int>(), cells);
  }
  for (const nlohmann::json& e : summary.value("equal_time", nlohmann::json::array())) {
    std::string cells;
    for (const auto& [name, v] : e["integrators"].items())
      cells += fmt::format("{}{} {:.4g}", cells.empty() ? "" : ", ", name,
                           v["mean_rel_mse"].get<double>());
    s += fmt::format("equal time on {} ({} threads, {:g} s): relMSE {}\n",
                     e["scene"].get<std::string>(), e["threads"].get<int>(),
                     e["seconds"].get<double>(), cells);
  }
  for (const nlohmann::json& b : summary["best"]) {
    s += fmt::format("most efficient on {} ({} threads, {} budgets): {}",
                     b["scene"].get<std::string>(), b["threads"].get<int>(),
                     b["budget_type"].get<std::string>(), b["integrator"].get<std::string>());
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
