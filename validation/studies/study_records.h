// What every study shares: its progress, the integrators it compares, and the records it
// writes, one per JSON line, so that an interrupted study resumes where it stopped.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "integrators/integrator_settings.h"
#include "loader/scene_loader.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/machine_info.h"
#include "validation/studies/record_fields.h"

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

// A study's JSON Lines output, and whether it holds a run already, so that a resumed study
// skips what it has done.
class StudyOutput {
 public:
  virtual ~StudyOutput() = default;
  virtual bool has(const nlohmann::json& record) const = 0;
  // Removes a truncated last line (a run cut off while writing its record; that run is not
  // counted as done, so it is redone) and says so in `log`. Before appending.
  void repairTruncatedLine(const std::function<void(const std::string&)>& log);
  // Appends the record, flushed to the file before returning.
  void append(const nlohmann::json& record);

 protected:
  // Reads the records already in `file`; a corrupt line other than a truncated last one is
  // an error naming the file and the line.
  explicit StudyOutput(std::filesystem::path file);
  // Calls `remember` with each record of `study` already in the file ("study" is required).
  void rememberRecords(const std::string& study);
  virtual void remember(const FieldReader& record) = 0;
  const std::string& fileName() const { return fileName_; }

 private:
  std::filesystem::path file_;
  std::string fileName_;
  JsonLinesFile read_;
};

// The output of a study whose runs are told apart by a Key (a struct ordered by its fields)
// read from a record, so that a record lacking a field of the key is an error naming the
// file, the record and the field.
template <typename Key>
class KeyedStudyOutput final : public StudyOutput {
 public:
  using ReadKey = Key (*)(const FieldReader&);
  KeyedStudyOutput(std::filesystem::path file, const std::string& study, ReadKey readKey)
      : StudyOutput(std::move(file)), readKey_(readKey) {
    rememberRecords(study);
  }
  bool has(const nlohmann::json& record) const override {
    return done_.count(readKey_(FieldReader(record, fileName(), "a new record"))) > 0;
  }

 private:
  void remember(const FieldReader& record) override { done_.insert(readKey_(record)); }

  ReadKey readKey_;
  std::set<Key> done_;
};

// The fields that say which render a record is of; its key is drawn from them.
nlohmann::json recordHeader(const std::string& study, const std::filesystem::path& scene,
                            const Vector2i& resolution, const IntegratorSettings& settings);
// The fields that say where and when a record was measured, and the revision the program was
// built from.
nlohmann::json provenance(const MachineInfo& machine);

}  // namespace verity::studies
