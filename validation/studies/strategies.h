// The BDPT strategies study: each strategy's share of the image.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "validation/studies/study_records.h"

namespace verity::studies {

struct StrategiesConfig {
  std::filesystem::path scene;
  int spp = 64;
  int resolution = 0;  // image width; 0: the scene's
  // BDPT keeps (k + 1)(k + 4) films for max bounces k, so the scene's usual 64 is out of reach;
  // the record says how much of the full image the strategies up to k account for.
  int maxBounces = 6;
  int threads = 0;                  // 0: all cores
  std::filesystem::path reference;  // optional: the full image, for the share beyond k
  std::filesystem::path output = "strategies.jsonl";
};

// One BDPT render with the MIS-weighted image of every strategy (s, t), reduced to each
// strategy's share of the image: its mean over pixels and channels divided by the image's.
// The shares add up to 1. Skipped if a record of the same scene, resolution, max bounces and
// spp is already in the output.
StudyProgress runStrategiesStudy(const StrategiesConfig& config,
                                 const std::function<void(const std::string&)>& log);

}  // namespace verity::studies
