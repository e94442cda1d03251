// What every study shares: its progress, the integrators it compares, and the records it
// writes, one per JSON line, so that an interrupted study resumes where it stopped.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "integrators/integrator_settings.h"
#include "scene/scene_loader.h"
#include "validation/studies/machine_info.h"

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

// A study's JSON Lines output and the keys of the records of that study already in it, so
// that a resumed study skips what it has done.
class StudyOutput {
 public:
  using Key = std::string (*)(const nlohmann::json&);
  StudyOutput(std::filesystem::path file, const std::string& study, Key key);
  bool has(const nlohmann::json& record) const { return done_.count(key_(record)) > 0; }
  // Appends the record, flushed to the file before returning.
  void append(const nlohmann::json& record);

 private:
  std::filesystem::path file_;
  Key key_;
  std::set<std::string> done_;
};

// The fields that say which render a record is of; its key is drawn from them.
nlohmann::json recordHeader(const std::string& study, const std::filesystem::path& scene,
                            const Vector2i& resolution, const IntegratorSettings& settings);
// The fields that say where and when a record was measured.
nlohmann::json provenance(const MachineInfo& machine, const std::string& revision);

}  // namespace verity::studies
