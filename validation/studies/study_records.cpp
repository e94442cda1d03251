#include "validation/studies/study_records.h"

#include <fmt/format.h>

#include "core/error.h"
#include "core/version.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/study_scene.h"

namespace verity::studies {

std::vector<PreparedIntegrator> prepareIntegrators(const SceneFile& file,
                                                   const std::vector<std::string>& names,
                                                   int maxBounces) {
  if (names.empty()) throw VerityError("", "--integrator", "no integrator given");
  std::vector<PreparedIntegrator> out;
  for (const std::string& name : names) {
    PreparedIntegrator p;
    p.settings = studyIntegrator(file, name, maxBounces);
    p.integrator = makeIntegrator(p.settings);
    out.push_back(std::move(p));
  }
  return out;
}

StudyOutput::StudyOutput(std::filesystem::path file)
    : file_(std::move(file)), fileName_(file_.string()), read_(readJsonLinesFile(file_)) {}

void StudyOutput::rememberRecords(const std::string& study) {
  for (size_t i = 0; i < read_.records.size(); ++i) {
    const FieldReader record(read_.records[i], fileName_, fmt::format("record {}", i + 1));
    if (record.text("study") == study) remember(record);
  }
}

void StudyOutput::repairTruncatedLine(const std::function<void(const std::string&)>& log) {
  if (!read_.truncatedLine) return;
  removeTruncatedLine(file_, read_);
  if (log)
    log(
        fmt::format("{}: line {}: removed a truncated record (a run cut off while writing it); "
                    "that run is redone",
                    file_.string(), *read_.truncatedLine));
  read_.truncatedLine.reset();
}

void StudyOutput::append(const nlohmann::json& record) {
  appendJsonLine(file_, record);
  remember(FieldReader(record, fileName_, "a new record"));
}

nlohmann::json recordHeader(const std::string& study, const std::filesystem::path& scene,
                            const Vector2i& resolution, const IntegratorSettings& settings) {
  return {
      {"study", study},
      {"scene", scene.stem().string()},
      {"scene_file", scene.string()},
      {"width", resolution.x()},
      {"height", resolution.y()},
      {"integrator", settings.type->name},
      {"max_bounces", settings.maxBounces},
  };
}

nlohmann::json provenance(const MachineInfo& machine) {
  nlohmann::json fields = toJson(machine);
  fields.update({{"revision", kRevision}, {"time", timestamp()}});
  return fields;
}

}  // namespace verity::studies
