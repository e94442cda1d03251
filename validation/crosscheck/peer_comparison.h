// Our integrators against an independent renderer's renders of the same scene: the comparison
// both cross-checks run (pbrt-v3 in pbrt_crosscheck_test.cpp, pbrt-v4 in
// pbrt4_crosscheck_test.cpp). Both sides are batch means per tile (batch_regions.h): ours
// from independent batches, the peer's from its renders with independent seeds, so the
// reference's own noise enters through its renders' spread (df = renders − 1).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "loader/scene_loader.h"
#include "validation/compare/comparison_family.h"

namespace verity::validation {

// The peer's renders in `folder` whose names start with `prefix`, in name order.
std::vector<std::filesystem::path> peerRenders(const std::filesystem::path& folder,
                                               const std::string& prefix);

struct PeerComparison {
  std::string peer;       // "pbrt-v3", named in the keys' statistics and the printed table
  std::string keyPrefix;  // before "<scene> <integrator>": the seeds derive from the key
  int tileSize = 16;
  int batches = 16;
  int batchSpp = 16;
};

// Renders each integrator of `scene` in batches, with the sampler that the case (sceneIndex,
// integrator's index) takes in turn (suite_samplers.h), adds its per-tile tests against the
// peer's renders to `family` and prints a table row with the whole image's relative difference
// per channel (± 1 standard error). Returns the number of invalid samples over all integrators.
uint64_t compareWithPeer(const PeerComparison& setup, SceneFile file, int sceneIndex,
                         const std::string& scene,
                         const std::vector<std::filesystem::path>& renders,
                         const std::vector<const char*>& integrators, ComparisonFamily& family);

}  // namespace verity::validation
