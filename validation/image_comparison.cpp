#include "validation/image_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "validation/stats/power.h"

namespace verity::validation {

namespace {

void checkOptions(const ComparisonOptions& o) {
  if (o.tileSize < 1)
    throw VerityError("", "--tile",
                      fmt::format("the tile size must be at least 1, not {}", o.tileSize));
  if (!(o.alpha > 0 && o.alpha < 1))
    throw VerityError("", "--alpha",
                      fmt::format("the family-wise level must lie in (0, 1), not {}", o.alpha));
  if (o.minSamples < 2)
    throw VerityError("", "min samples", "a pixel needs at least 2 samples for a sample variance");
  if (!(o.power > 0 && o.power < 1)) throw VerityError("", "power", "the power must lie in (0, 1)");
}

std::string attribute(const PixelStatistics& s, const std::string& key) {
  auto it = s.attributes.find(key);
  return it == s.attributes.end() ? std::string() : it->second;
}

void addWarnings(const PixelStatistics& a, const PixelStatistics& b, ComparisonResult& r) {
  const std::string seedA = attribute(a, "verity:seed"), seedB = attribute(b, "verity:seed");
  if (!seedA.empty() && seedA == seedB)
    r.warnings.push_back(fmt::format(
        "both images were rendered with seed {}: the test assumes independent renders, and "
        "renders sharing random numbers are correlated",
        seedA));
  const std::string bouncesA = attribute(a, "verity:max_bounces");
  const std::string bouncesB = attribute(b, "verity:max_bounces");
  if (!bouncesA.empty() && !bouncesB.empty() && bouncesA != bouncesB)
    r.warnings.push_back(
        fmt::format("max_bounces differs ({} and {}): the images estimate different quantities",
                    bouncesA, bouncesB));
  const std::string sceneA = attribute(a, "verity:scene"), sceneB = attribute(b, "verity:scene");
  if (!sceneA.empty() && !sceneB.empty() && sceneA != sceneB)
    r.warnings.push_back(fmt::format("the scenes differ (\"{}\" and \"{}\")", sceneA, sceneB));
}

double relativeDifference(double a, double b) {
  const double scale = 0.5 * (std::abs(a) + std::abs(b));
  return scale > 0 ? (b - a) / scale : 0.0;
}

}  // namespace

std::vector<size_t> ComparisonResult::worst(size_t count) const {
  std::vector<size_t> order(tests.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) {
    if (tests[i].welch.p != tests[j].welch.p) return tests[i].welch.p < tests[j].welch.p;
    return std::abs(tests[i].relativeDifference) > std::abs(tests[j].relativeDifference);
  });
  order.resize(std::min(count, order.size()));
  return order;
}

ComparisonResult compareImages(const PixelStatistics& a, const PixelStatistics& b,
                               const ComparisonOptions& options) {
  checkOptions(options);
  if (a.width != b.width || a.height != b.height)
    throw VerityError(a.label, "",
                      fmt::format("cannot compare {}x{} pixels with {}x{} pixels in \"{}\": the "
                                  "images must have the same resolution",
                                  a.width, a.height, b.width, b.height, b.label));
  ComparisonResult r;
  r.options = options;
  r.labelA = a.label;
  r.labelB = b.label;
  r.width = a.width;
  r.height = a.height;
  const int ts = options.tileSize;
  r.tilesX = (a.width + ts - 1) / ts;
  r.tilesY = (a.height + ts - 1) / ts;
  addWarnings(a, b, r);

  for (int ty = 0; ty < r.tilesY; ++ty)
    for (int tx = 0; tx < r.tilesX; ++tx) {
      const TileRect rect{tx * ts, ty * ts, std::min((tx + 1) * ts, a.width),
                          std::min((ty + 1) * ts, a.height)};
      bool tested = false;
      for (int c = 0; c < kChannels; ++c) {
        TileTest t;
        t.tileX = tx;
        t.tileY = ty;
        t.rect = rect;
        t.channel = c;
        t.pooled = poolTile(a, b, rect, c, options.minSamples);
        if (c == 0) r.pixelsExcluded += t.pooled.excluded;
        if (t.pooled.pixels == 0) continue;
        tested = true;
        t.welch = welchTest(t.pooled.a, t.pooled.b);
        t.relativeDifference = relativeDifference(t.pooled.a.mean, t.pooled.b.mean);
        r.deterministicTests += t.welch.deterministic;
        r.tests.push_back(t);
      }
      (tested ? r.tilesTested : r.tilesUntested) += 1;
    }
  if (r.tests.empty())
    throw VerityError(a.label, "",
                      fmt::format("no tile of this image and \"{}\" can be tested: no pixel has "
                                  "at least {} samples in both (render with more samples per "
                                  "pixel)",
                                  b.label, options.minSamples));

  std::vector<double> p(r.tests.size());
  for (size_t i = 0; i < p.size(); ++i) p[i] = r.tests[i].welch.p;
  r.holm = holmBonferroni(p, options.alpha);
  for (size_t i = 0; i < p.size(); ++i) {
    r.tests[i].adjustedP = r.holm.adjusted[i];
    r.tests[i].rejected = r.holm.rejected[i];
  }
  r.smallestP = *std::min_element(p.begin(), p.end());
  r.differ = r.holm.rejections > 0;

  int channelsTested = 0;
  double smallestKs = 1;
  for (int c = 0; c < kChannels; ++c) {
    std::vector<double> values;
    for (const TileTest& t : r.tests)
      if (t.channel == c && !t.welch.deterministic) values.push_back(t.welch.p);
    r.uniformity[c] = ksTestUniform(values);
    if (r.uniformity[c].n > 0) {
      ++channelsTested;
      smallestKs = std::min(smallestKs, r.uniformity[c].pValue);
    }
  }
  r.uniformityP = std::min(1.0, channelsTested * smallestKs);

  std::vector<PowerTerm> terms;
  for (const TileTest& t : r.tests)
    terms.push_back({0.5 * (t.pooled.a.mean + t.pooled.b.mean),
                     t.pooled.a.variance + t.pooled.b.variance, t.welch.df, t.channel});
  r.detectableBias =
      detectableRelativeBias(terms, static_cast<int>(r.tests.size()), options.alpha, options.power);
  return r;
}

}  // namespace verity::validation
