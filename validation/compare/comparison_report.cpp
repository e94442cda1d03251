#include "validation/compare/comparison_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
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

// "8 renders (a1.exr, ...): variance from their spread, df 7" or "one image with variance
// channels (a.exr): variance from its pixels' samples, Welch-Satterthwaite df".
std::string sideLine(const SideSummary& side) {
  if (!side.renderSet)
    return fmt::format(
        "one image with variance channels, {}: each tile's variance from its "
        "pixels' sample variances, Welch-Satterthwaite df",
        side.files.front());
  std::string s = fmt::format(
      "a set of {} renders, each tile's variance from their spread (df = {} - 1 = {}): {}",
      side.renders(), side.renders(), side.renders() - 1, fmt::join(side.files, ", "));
  for (size_t i = 0; i < side.files.size(); ++i)
    if (side.nonfinitePixels[i] > 0)
      s += fmt::format("\n   {} has {} pixels with a non-finite value: left out of both sides",
                       side.files[i], side.nonfinitePixels[i]);
  return s;
}

nlohmann::json sideJson(const SideSummary& side) {
  nlohmann::json j;
  j["kind"] = side.renderSet ? "render_set" : "variance_image";
  j["files"] = side.files;
  j["renders"] = side.renders();
  if (side.renderSet) {
    j["df"] = side.renders() - 1;
    j["nonfinite_pixels"] = side.nonfinitePixels;
  }
  return j;
}

// Median, smallest and largest finite per-test detectable bias.
std::string tileBiasLine(const ComparisonResult& r) {
  std::vector<double> biases;
  for (const TileTest& t : r.tests)
    if (!t.welch.deterministic && std::isfinite(t.detectableBias))
      biases.push_back(t.detectableBias);
  if (biases.empty()) return "none of the tests has a finite detectable bias";
  std::sort(biases.begin(), biases.end());
  return fmt::format("median {}, smallest {}, largest {} over {} of {} tests",
                     percent(biases[biases.size() / 2]), percent(biases.front()),
                     percent(biases.back()), biases.size(), r.tests.size());
}

// "rejected tiles (x,y channels): (2,0 RGB) (3,1 G) ...", at most kListed tiles.
std::string rejectedTilesLine(const ComparisonResult& r) {
  constexpr int kListed = 24;
  std::vector<std::string> tiles;
  int total = 0;
  for (size_t i = 0; i < r.tests.size();) {
    std::string channels;
    size_t j = i;
    for (; j < r.tests.size() && r.tests[j].tileX == r.tests[i].tileX &&
           r.tests[j].tileY == r.tests[i].tileY;
         ++j)
      if (r.tests[j].rejected) channels += kChannelNames[r.tests[j].channel];
    if (!channels.empty() && ++total <= kListed)
      tiles.push_back(fmt::format("({},{} {})", r.tests[i].tileX, r.tests[i].tileY, channels));
    i = j;
  }
  return fmt::format("rejected tiles (x,y channels): {}{}\n", fmt::join(tiles, " "),
                     total > kListed ? fmt::format(" and {} more", total - kListed) : "");
}

}  // namespace

std::string comparisonSummary(const ComparisonResult& r, size_t worstCount) {
  const auto& o = r.options;
  std::string s;
  s += fmt::format("A: {}\nB: {}\n", sideLine(r.sideA), sideLine(r.sideB));
  s += fmt::format(
      "{}x{} pixels in {}x{}-pixel tiles: {} tiles tested, {} untested (no pixel usable on "
      "both sides); {} pixels left out (fewer than {} samples in an image with variances, or "
      "a non-finite value in a set)\n",
      r.width, r.height, o.tileSize, o.tileSize, r.tilesTested, r.tilesUntested, r.pixelsExcluded,
      o.minSamples);
  s += fmt::format(
      "Welch t-test per tile and channel (R, G, B): {} tests, {} deterministic (zero variance "
      "in both)\n",
      r.tests.size(), r.deterministicTests);
  s += fmt::format("smallest p: {:.3g}\n", r.smallestP);
  s += fmt::format("Holm-Bonferroni at family-wise level {}: {} of {} tests rejected\n",
                   percent(o.alpha), r.holm.rejections, r.tests.size());
  if (r.holm.rejections > 0) s += rejectedTilesLine(r);
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
  s += fmt::format(
      "per test, the smallest relative bias of its tile detected with {:.0f}% probability at "
      "the Bonferroni level {:.3g} (alpha / {} tests; Holm rejects at least as much): {}\n",
      100 * o.power, o.alpha / r.tests.size(), r.tests.size(), tileBiasLine(r));
  s += "smallest p-values:\n";
  for (size_t i : r.worst(worstCount)) {
    const TileTest& t = r.tests[i];
    s += fmt::format(
        "  tile ({},{}) pixels [{},{})x[{},{}) {}: A {:.6g} B {:.6g} rel {:+.3g}% t {:.3g} "
        "df {:.4g} p {:.3g} Holm {:.3g} detectable {}{}\n",
        t.tileX, t.tileY, t.rect.x0, t.rect.x1, t.rect.y0, t.rect.y1, kChannelNames[t.channel],
        t.pooled.a.mean, t.pooled.b.mean, 100 * t.relativeDifference, t.welch.t, t.welch.df,
        t.welch.p, t.adjustedP, percent(t.detectableBias), t.rejected ? " REJECTED" : "");
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
  j["side_a"] = sideJson(r.sideA);
  j["side_b"] = sideJson(r.sideB);
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
                     {"z", number(t.z)},
                     {"detectable_relative_bias", number(t.detectableBias)},
                     {"df", number(t.welch.df)},
                     {"p", t.welch.p},
                     {"holm_adjusted_p", t.adjustedP},
                     {"rejected", t.rejected},
                     {"deterministic", t.welch.deterministic}});
  return j;
}

}  // namespace verity::validation
