#include "validation/studies/summary_records.h"

#include <fmt/format.h>

#include "core/error.h"

namespace verity::studies {

namespace {

// Reads the required fields of one JSON object, naming the file, the record and the key in
// its errors.
class FieldReader {
 public:
  FieldReader(const nlohmann::json& object, const std::string& file, std::string where)
      : object_(object), file_(file), where_(std::move(where)) {}

  const nlohmann::json& field(const char* key) const {
    const auto it = object_.find(key);
    if (it == object_.end()) fail(key, "missing key");
    return *it;
  }
  std::string text(const char* key) const {
    const nlohmann::json& v = field(key);
    if (!v.is_string()) fail(key, "expected a string, found " + v.dump());
    return v.get<std::string>();
  }
  double number(const char* key) const {
    const nlohmann::json& v = field(key);
    if (!v.is_number()) fail(key, "expected a number, found " + v.dump());
    return v.get<double>();
  }
  int integer(const char* key) const {
    const nlohmann::json& v = field(key);
    if (!v.is_number_integer()) fail(key, "expected an integer, found " + v.dump());
    return v.get<int>();
  }
  const nlohmann::json& array(const char* key) const {
    const nlohmann::json& v = field(key);
    if (!v.is_array()) fail(key, "expected an array, found " + v.dump());
    return v;
  }
  const std::string& where() const { return where_; }

 private:
  [[noreturn]] void fail(const char* key, const std::string& problem) const {
    throw VerityError(file_, fmt::format("{}, \"{}\"", where_, key), problem);
  }

  const nlohmann::json& object_;
  const std::string& file_;
  std::string where_;
};

ConvergenceRun convergenceRun(const FieldReader& r) {
  ConvergenceRun c;
  c.scene = r.text("scene");
  c.width = r.integer("width");
  c.height = r.integer("height");
  c.integrator = r.text("integrator");
  c.maxBounces = r.integer("max_bounces");
  c.threads = r.integer("threads");
  c.budgetType = r.text("budget_type");
  c.budget = r.number("budget");
  c.spp = r.integer("spp");
  c.wallSeconds = r.number("wall_seconds");
  c.cpuSeconds = r.number("cpu_seconds");
  c.relMse = r.number("rel_mse");
  c.relVariance = r.number("rel_variance");
  c.relMseEpsilon = r.number("rel_mse_epsilon");
  c.referenceRelMse = r.number("reference_rel_mse");
  return c;
}

SpeedupRun speedupRun(const FieldReader& r) {
  SpeedupRun s;
  s.scene = r.text("scene");
  s.width = r.integer("width");
  s.height = r.integer("height");
  s.integrator = r.text("integrator");
  s.maxBounces = r.integer("max_bounces");
  s.spp = r.integer("spp");
  s.threads = r.integer("threads");
  s.wallSeconds = r.number("wall_seconds");
  s.cpuSeconds = r.number("cpu_seconds");
  return s;
}

StrategiesRun strategiesRun(const FieldReader& r, const nlohmann::json& record,
                            const std::string& file) {
  StrategiesRun s;
  s.scene = r.text("scene");
  s.width = r.integer("width");
  s.height = r.integer("height");
  s.maxBounces = r.integer("max_bounces");
  s.spp = r.integer("spp");
  s.run = r.integer("run");
  const nlohmann::json& list = r.array("strategies");
  for (size_t i = 0; i < list.size(); ++i) {
    const FieldReader st(list[i], file, fmt::format("{}, \"strategies\"[{}]", r.where(), i));
    s.strategies.push_back({st.integer("s"), st.integer("t"), st.number("share"), list[i]});
  }
  if (record.contains("share_beyond_max_bounces"))
    s.shareBeyondMaxBounces = record["share_beyond_max_bounces"];
  return s;
}

}  // namespace

void addSummaryRecords(const std::vector<nlohmann::json>& records, const std::string& file,
                       SummaryRecords& out) {
  for (size_t i = 0; i < records.size(); ++i) {
    const FieldReader r(records[i], file, fmt::format("record {}", i + 1));
    const std::string study = r.text("study");
    if (study == "convergence")
      out.convergence.push_back(convergenceRun(r));
    else if (study == "speedup")
      out.speedup.push_back(speedupRun(r));
    else if (study == "strategies")
      out.strategies.push_back(strategiesRun(r, records[i], file));
  }
}

}  // namespace verity::studies
