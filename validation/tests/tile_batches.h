// Per-tile batch means of a scene's renders, for the Welch suites that compare two ways of
// rendering one scene: `batches` renders of `spp` samples, each with its own seed derived from
// `key`, pooled over square tiles (batch_regions.h), so that the tiles' variances come from
// independent renders whatever correlates the pixels or the samples of one render.
#pragma once

#include <string>

#include "render/render_batches.h"
#include "validation/compare/batch_regions.h"

namespace verity::validation::testing {

inline PixelStatistics renderTileBatches(const SceneFile& file, const std::string& integrator,
                                         int maxBounces, int batches, int spp, int tileSize,
                                         const std::string& key) {
  const Vector2i res = file.scene->camera().resolution();
  int tiles = 0;
  const std::vector<int> regionOf = tileRegions(res.x(), res.y(), tileSize, &tiles);
  BatchRegions out(regionOf, tiles, key);
  renderBatches(file, integrator, maxBounces, batches, spp, key,
                [&](const Film& film) { out.addBatch(film); });
  return out.statistics();
}

}  // namespace verity::validation::testing
