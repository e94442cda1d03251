// Reference images: a long render saved with its per-pixel variance, so that a study can
// measure errors against it and say how much of them the reference itself contributes.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "distributed/process_group.h"

namespace verity::studies {

struct ReferenceConfig {
  std::filesystem::path scene;
  int spp = 4096;
  std::string integrator;  // "" : the scene's
  int maxBounces = -1;     // < 0: the scene's
  int threads = 0;         // 0: all cores
  int resolution = 0;      // image width (the scene's aspect ratio is kept); 0: the scene's
  std::filesystem::path directory = "references";
  uint64_t seed = 0;  // 0: derived from the scene name (never equal to a study run's seed)
};

struct ReferenceResult {
  std::filesystem::path image, sidecar;
  nlohmann::json metadata;  // what the sidecar holds
};

// Writes <directory>/<scene>.exr (R, G, B means; variance.R/G/B, the variance of one sample;
// samples; ZIP; half floats where they hold every value, else 32-bit floats; never Inf: a
// value beyond 32-bit floats is an error) and <directory>/<scene>.json: integrator, spp, seed,
// times, threads, machine, source revision and the reference's own estimated relative MSE, mean
// over pixels and channels of (variance / samples) / (mean² + ε). Over a distributed `group` the
// ranks share the passes (the image is the same bits) and rank 0 alone writes; the other ranks get
// an empty result.
ReferenceResult makeReference(const ReferenceConfig& config,
                              const ProcessGroup& group = ProcessGroup::solo());

}  // namespace verity::studies
