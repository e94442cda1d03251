// The speed-up study: each integrator timed at each thread count on the same seeded work.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "distributed/process_group.h"
#include "validation/studies/study_records.h"

namespace verity::studies {

struct SpeedupConfig {
  std::filesystem::path scene;
  std::vector<std::string> integrators;
  std::vector<int> threads = {1, 2};
  int spp = 16;
  int repeats = 3;
  int resolution = 0;  // image width; 0: the scene's
  int maxBounces = -1;
  std::filesystem::path output = "speedup.jsonl";
};

// Times each integrator at each thread count; thread counts alternate (forwards, then
// backwards) within every repeat. Every render of an integrator uses the same seed, so all
// do the same work (renders are bit-identical across thread counts). Runs whose key (scene,
// resolution, integrator, max bounces, threads, spp, repeat) is already in the output are
// skipped. Over a distributed `group` the renders are dealt to its ranks
// (validation/studies/run_distribution.h).
StudyProgress runSpeedupStudy(const SpeedupConfig& config,
                              const std::function<void(const std::string&)>& log,
                              const ProcessGroup& group = ProcessGroup::solo());

}  // namespace verity::studies
