#include "validation/comparison_report.h"

#include <fmt/format.h>

#include <cmath>

namespace verity::validation {

namespace {

std::string percent(double x) {
  if (std::isinf(x)) return "none";
  return fmt::format("{:.3g}%", 100 * x);
}

// JSON has no infinity: write null.
nlohmann::json number(double x) {
  return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

}  // namespace

std::string comparisonSummary(const ComparisonResult& r, size_t worstCount) {
  const auto& o = r.options;
  std::string s;
  s += fmt::format("A: {}\nB: {}\n", r.labelA, r.labelB);
  s += fmt::format(
      "{}x{} pixels in {}x{}-pixel tiles: {} tiles tested, {} untested (no pixel with {}+ "
      "samples in both); {} pixels left out\n",
      r.width, r.height, o.tileSize, o.tileSize, r.tilesTested, r.tilesUntested, o.minSamples,
      r.pixelsExcluded);
  s += fmt::format(
      "Welch t-test per tile and channel (R, G, B): {} tests, {} deterministic (zero variance "
      "in both)\n",
      r.tests.size(), r.deterministicTests);
  s += fmt::format("smallest p: {:.3g}\n", r.smallestP);
  s += fmt::format("Holm-Bonferroni at family-wise level {}: {} of {} tests rejected\n",
                   percent(o.alpha), r.holm.rejections, r.tests.size());
  std::string perChannel;
  for (int c = 0; c < kChannels; ++c)
    perChannel += r.uniformity[c].n > 0
                      ? fmt::format("{}{} {:.3g} (n {})", c ? ", " : "", kChannelNames[c],
                                    r.uniformity[c].pValue, r.uniformity[c].n)
                      : fmt::format("{}{} -", c ? ", " : "", kChannelNames[c]);
  s += fmt::format(
      "p-value uniformity (Kolmogorov-Smirnov vs U(0,1), Bonferroni over channels): p = {:.3g} "
      "[{}]{}\n",
      r.uniformityP, perChannel,
      r.uniformityP <= o.alpha
          ? " -- NOT uniform: a bias spread over many tiles, correlated tiles or heavy-tailed "
            "samples (diagnostic only)"
          : "");
  s += fmt::format(
      "power: a uniform brightness bias of {} would be detected with {:.0f}% "
      "probability\n",
      percent(r.detectableBias), 100 * o.power);
  s += "smallest p-values:\n";
  for (size_t i : r.worst(worstCount)) {
    const TileTest& t = r.tests[i];
    s += fmt::format(
        "  tile ({},{}) pixels [{},{})x[{},{}) {}: A {:.6g} B {:.6g} rel {:+.3g}% t {:.3g} "
        "df {:.4g} p {:.3g} Holm {:.3g}{}\n",
        t.tileX, t.tileY, t.rect.x0, t.rect.x1, t.rect.y0, t.rect.y1, kChannelNames[t.channel],
        t.pooled.a.mean, t.pooled.b.mean, 100 * t.relativeDifference, t.welch.t, t.welch.df,
        t.welch.p, t.adjustedP, t.rejected ? " REJECTED" : "");
  }
  for (const std::string& w : r.warnings) s += "warning: " + w + "\n";
  s += r.differ ? fmt::format(
                      "verdict: DIFFER ({} tests reject equal means at family-wise "
                      "level {})\n",
                      r.holm.rejections, percent(o.alpha))
                : fmt::format(
                      "verdict: AGREE (no test rejects equal means at family-wise level "
                      "{})\n",
                      percent(o.alpha));
  return s;
}

nlohmann::json comparisonJson(const ComparisonResult& r) {
  nlohmann::json j;
  j["a"] = r.labelA;
  j["b"] = r.labelB;
  j["width"] = r.width;
  j["height"] = r.height;
  j["tile_size"] = r.options.tileSize;
  j["alpha"] = r.options.alpha;
  j["min_samples"] = r.options.minSamples;
  j["tiles_tested"] = r.tilesTested;
  j["tiles_untested"] = r.tilesUntested;
  j["pixels_excluded"] = r.pixelsExcluded;
  j["tests"] = r.tests.size();
  j["deterministic_tests"] = r.deterministicTests;
  j["smallest_p"] = r.smallestP;
  j["holm_rejections"] = r.holm.rejections;
  j["differ"] = r.differ;
  j["uniformity_p"] = r.uniformityP;
  for (int c = 0; c < kChannels; ++c)
    j["uniformity"][kChannelNames[c]] = {{"n", r.uniformity[c].n},
                                         {"ks_statistic", r.uniformity[c].statistic},
                                         {"p", r.uniformity[c].pValue}};
  j["power"] = r.options.power;
  j["detectable_relative_bias"] = number(r.detectableBias);
  j["warnings"] = r.warnings;
  auto& tiles = j["tile_tests"] = nlohmann::json::array();
  for (const TileTest& t : r.tests)
    tiles.push_back({{"tile", {t.tileX, t.tileY}},
                     {"pixels_x", {t.rect.x0, t.rect.x1}},
                     {"pixels_y", {t.rect.y0, t.rect.y1}},
                     {"channel", kChannelNames[t.channel]},
                     {"pixels", t.pooled.pixels},
                     {"mean_a", t.pooled.a.mean},
                     {"mean_b", t.pooled.b.mean},
                     {"variance_a", t.pooled.a.variance},
                     {"variance_b", t.pooled.b.variance},
                     {"relative_difference", t.relativeDifference},
                     {"t", t.welch.t},
                     {"df", number(t.welch.df)},
                     {"p", t.welch.p},
                     {"holm_adjusted_p", t.adjustedP},
                     {"rejected", t.rejected},
                     {"deterministic", t.welch.deterministic}});
  return j;
}

}  // namespace verity::validation
