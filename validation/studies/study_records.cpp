#include "validation/studies/study_records.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/error.h"
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

StudyOutput::StudyOutput(std::filesystem::path file, const std::string& study, Key key)
    : file_(std::move(file)),
      fileName_(file_.string()),
      read_(readJsonLinesFile(file_)),
      key_(key) {
  for (size_t i = 0; i < read_.records.size(); ++i)
    if (read_.records[i].value("study", "") == study)
      done_.insert(this->key(read_.records[i], fmt::format("record {}", i + 1)));
}

std::string StudyOutput::key(const nlohmann::json& record, const std::string& where) const {
  return key_(FieldReader(record, fileName_, where));
}

bool StudyOutput::has(const nlohmann::json& record) const {
  return done_.count(key(record, "a new record")) > 0;
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
  done_.insert(key(record, "a new record"));
}

void checkBudgets(const std::string& type, const std::vector<double>& budgets) {
  if (type != "spp" && type != "time")
    throw VerityError(
        "", "--spp/--time",
        "the budget is samples per pixel (--spp) or seconds (--time), not \"" + type + "\"");
  if (budgets.empty()) throw VerityError("", "--spp/--time", "no budget given");
  for (double b : budgets) {
    if (!(b > 0))
      throw VerityError("", "--" + type, fmt::format("budgets must be positive, not {}", b));
    if (type == "spp" && (b != std::floor(b) || b > std::numeric_limits<int>::max()))
      throw VerityError("", "--spp",
                        fmt::format("samples per pixel must be a whole number, not {}", b));
  }
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

nlohmann::json provenance(const MachineInfo& machine, const std::string& revision) {
  return {
      {"hostname", machine.hostname}, {"cpu_model", machine.cpuModel}, {"cores", machine.cores},
      {"revision", revision},         {"time", timestamp()},
  };
}

}  // namespace verity::studies
