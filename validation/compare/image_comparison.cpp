#include "validation/compare/image_comparison.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "validation/compare/variance_image_side.h"

namespace verity::validation {

void checkComparisonOptions(const ComparisonOptions& o) {
  if (o.tileSize < 1)
    throw VerityError("", "--tile",
                      fmt::format("the tile size must be at least 1 pixel, not {}", o.tileSize));
  if (!(o.alpha > 0 && o.alpha < 1))
    throw VerityError("", "--alpha",
                      fmt::format("the family-wise level must lie strictly between 0 and 1, "
                                  "not {}",
                                  o.alpha));
  if (o.minSamples < 2)
    throw VerityError("", "min samples", "a pixel needs at least 2 samples for a sample variance");
  if (!(o.power > 0 && o.power < 1)) throw VerityError("", "power", "the power must lie in (0, 1)");
}

namespace {

using FileAttributes = std::vector<std::pair<std::string, std::map<std::string, std::string>>>;

// Warnings about what the files' Verity attributes say: two renders sharing a seed (the
// test assumes independent renders), or files estimating different quantities.
void addWarnings(const FileAttributes& files, ComparisonResult& r) {
  std::map<std::string, std::string> seen;  // seed → first file with it
  std::map<std::string, std::string> bounces, scenes;
  for (const auto& entry : files) {
    // Named, not a structured binding: clang before 16 cannot capture those in a lambda.
    const std::string& file = entry.first;
    const std::map<std::string, std::string>& attributes = entry.second;
    const auto get = [&](const char* key) {
      const auto it = attributes.find(key);
      return it == attributes.end() ? std::string() : it->second;
    };
    const std::string seed = get("verity:seed");
    if (!seed.empty() && !seen.emplace(seed, file).second)
      r.warnings.push_back(fmt::format(
          "\"{}\" and \"{}\" were both rendered with seed {}: the test assumes independent "
          "renders, and renders sharing random numbers are correlated",
          seen[seed], file, seed));
    if (!get("verity:max_bounces").empty()) bounces.emplace(get("verity:max_bounces"), file);
    if (!get("verity:scene").empty()) scenes.emplace(get("verity:scene"), file);
  }
  if (bounces.size() > 1)
    r.warnings.push_back(fmt::format(
        "max_bounces differs (\"{}\" has {}, \"{}\" has {}): the images estimate different "
        "quantities",
        bounces.begin()->second, bounces.begin()->first, bounces.rbegin()->second,
        bounces.rbegin()->first));
  if (scenes.size() > 1)
    r.warnings.push_back(fmt::format("the scenes differ (\"{}\" and \"{}\")", scenes.begin()->first,
                                     scenes.rbegin()->first));
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

ComparisonResult compareSides(const ComparisonSide& a, const ComparisonSide& b,
                              const ComparisonOptions& options) {
  checkComparisonOptions(options);
  if (a.width() != b.width() || a.height() != b.height())
    throw VerityError(a.label(), "",
                      fmt::format("cannot compare {}x{} pixels with {}x{} pixels in \"{}\": the "
                                  "images must have the same resolution",
                                  a.width(), a.height(), b.width(), b.height(), b.label()));
  ComparisonResult r;
  r.options = options;
  r.labelA = a.label();
  r.labelB = b.label();
  r.sideA = a.summary();
  r.sideB = b.summary();
  r.width = a.width();
  r.height = a.height();
  const TileGrid grid{a.width(), a.height(), options.tileSize};
  r.tilesX = grid.tilesX();
  r.tilesY = grid.tilesY();
  FileAttributes files = a.attributes();
  for (auto& f : b.attributes()) files.push_back(std::move(f));
  addWarnings(files, r);

  std::vector<char> usable = a.usablePixels(options.minSamples);
  const std::vector<char> usableB = b.usablePixels(options.minSamples);
  for (size_t i = 0; i < usable.size(); ++i) usable[i] = usable[i] && usableB[i];
  const auto estimatesA = a.tileEstimates(grid, usable);
  const auto estimatesB = b.tileEstimates(grid, usable);
  for (int ty = 0; ty < r.tilesY; ++ty)
    for (int tx = 0; tx < r.tilesX; ++tx) {
      const TileRect rect = grid.rect(tx, ty);
      int pixels = 0;
      for (int y = rect.y0; y < rect.y1; ++y)
        for (int x = rect.x0; x < rect.x1; ++x) pixels += usable[size_t(y) * r.width + x];
      r.pixelsExcluded += rect.area() - pixels;
      if (pixels == 0) {
        ++r.tilesUntested;
        continue;
      }
      ++r.tilesTested;
      const int tile = ty * r.tilesX + tx;
      for (int c = 0; c < kChannels; ++c) {
        TileTest t;
        t.tileX = tx;
        t.tileY = ty;
        t.rect = rect;
        t.channel = c;
        t.pooled = {estimatesA[tile][c], estimatesB[tile][c], pixels, rect.area() - pixels};
        r.tests.push_back(t);
      }
    }
  if (r.tests.empty())
    throw VerityError(a.label(), "",
                      fmt::format("no tile of this image and \"{}\" can be tested: no pixel is "
                                  "usable in both (in an image with variances a pixel needs at "
                                  "least {} samples: render with more samples per pixel; in a "
                                  "set, finite values in every render)",
                                  b.label(), options.minSamples));
  static_cast<TileDecision&>(r) =
      decideTiles(r.tests, options.alpha, options.power, options.detectableBias);
  return r;
}

ComparisonResult compareImages(const PixelStatistics& a, const PixelStatistics& b,
                               const ComparisonOptions& options) {
  return compareSides(VarianceImageSide(a), VarianceImageSide(b), options);
}

}  // namespace verity::validation
