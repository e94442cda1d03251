// Independent seeded renders of one scene, for the suites that compare two ways of rendering it
// batch by batch.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "film/film.h"
#include "loader/scene_loader.h"

namespace verity {

// `batches` independent renders of `spp` samples per pixel with `integrator` (any accepted
// spelling; max bounces `maxBounces`, the file's when negative), batch i seeded by
// hashString("<key> batch <i>"); each film is handed to `onBatch`. Returns the invalid samples
// of all batches.
uint64_t renderBatches(const SceneFile& file, const std::string& integrator, int maxBounces,
                       int batches, int spp, const std::string& key,
                       const std::function<void(const Film&)>& onBatch);

}  // namespace verity
