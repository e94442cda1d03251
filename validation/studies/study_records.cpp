#include "validation/studies/study_records.h"

#include "core/error.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/study_scene.h"

namespace verity::studies {

std::vector<PreparedIntegrator> prepareIntegrators(const SceneFile& file,
                                                   const std::vector<std::string>& names,
                                                   int maxBounces) {
  if (names.empty()) throw VerityError("", "--integrators", "no integrator given");
  std::vector<PreparedIntegrator> out;
  for (const std::string& name : names) {
    PreparedIntegrator p;
    p.settings = studyIntegrator(file, name, maxBounces);
    p.integrator = makeIntegrator(p.settings);
    out.push_back(std::move(p));
  }
  return out;
}

StudyOutput::StudyOutput(std::filesystem::path file, const std::string& study, Key key)
    : file_(std::move(file)), key_(key) {
  for (const nlohmann::json& r : readJsonLines(file_))
    if (r.value("study", "") == study) done_.insert(key_(r));
}

void StudyOutput::append(const nlohmann::json& record) {
  appendJsonLine(file_, record);
  done_.insert(key_(record));
}

nlohmann::json recordHeader(const std::string& study, const std::filesystem::path& scene,
                            const Vector2i& resolution, const IntegratorSettings& settings) {
  return {
      {"study", study},
      {"scene", scene.stem().string()},
      {"scene_file", scene.string()},
      {"width", resolution.x()},
      {"height", resolution.y()},
      {"integrator", settings.type},
      {"max_bounces", settings.maxBounces},
  };
}

nlohmann::json provenance(const MachineInfo& machine, const std::string& revision) {
  return {
      {"hostname", machine.hostname}, {"cpu_model", machine.cpuModel}, {"cores", machine.cores},
      {"revision", revision},         {"time", timestamp()},
  };
}

}  // namespace verity::studies
