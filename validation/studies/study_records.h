// What every study shares: its progress, the integrators it compares, and the records it
// writes, one per JSON line, so that an interrupted study resumes where it stopped.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "validation/studies/study_util.h"

namespace verity::studies {

struct StudyProgress {
  int done = 0, skipped = 0, total = 0;
};

// An integrator as a study runs it.
struct PreparedIntegrator {
  IntegratorSettings settings;
  std::unique_ptr<Integrator> integrator;
};
// The scene's settings for each named integrator (any accepted spelling), max bounces
// overridden if ≥ 0; throws VerityError for an unknown name or none.
std::vector<PreparedIntegrator> prepareIntegrators(const SceneFile& file,
                                                   const std::vector<std::string>& names,
                                                   int maxBounces);

// The keys, by `key`, of the records of `study` already in `file` (none if it is missing).
std::set<std::string> existingKeys(const std::filesystem::path& file, const std::string& study,
                                   std::string (*key)(const nlohmann::json&));

// The fields that say which render a record is of; its key is drawn from them.
nlohmann::json recordHeader(const std::string& study, const std::filesystem::path& scene,
                            const Vector2i& resolution, const IntegratorSettings& settings);
// The fields that say where and when a record was measured.
nlohmann::json provenance(const MachineInfo& machine, const std::string& revision);

}  // namespace verity::studies
