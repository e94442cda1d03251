#include "validation/studies/summary_records.h"

#include <fmt/format.h>

#include "core/error.h"
#include "sampling/sampler_registry.h"
#include "validation/studies/record_fields.h"
#include "validation/studies/study_sampler.h"

namespace verity::studies {

namespace {

ConvergenceRun convergenceRun(const FieldReader& r) {
  ConvergenceRun c;
  c.scene = r.text("scene");
  c.width = r.integer("width");
  c.height = r.integer("height");
  c.integrator = r.text("integrator");
  c.sampler = r.text("sampler");
  const std::optional<bool> independent = samplerSamplesAreIndependent(c.sampler);
  if (!independent)
    r.fail("sampler",
           "unknown sampler \"" + c.sampler + "\" (expected one of " + samplerTypeList() + ")");
  c.maxBounces = r.integer("max_bounces");
  c.threads = r.integer("threads");
  c.budgetType = readBudgetType(r);
  c.budget = r.number("budget");
  c.spp = r.integer("spp");
  c.wallSeconds = r.number("wall_seconds");
  c.cpuSeconds = r.number("cpu_seconds");
  c.relMse = r.number("rel_mse");
  if (*independent) c.relVariance = r.number("rel_variance");
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

StrategiesRun strategiesRun(const FieldReader& r) {
  StrategiesRun s;
  s.scene = r.text("scene");
  s.width = r.integer("width");
  s.height = r.integer("height");
  s.maxBounces = r.integer("max_bounces");
  s.spp = r.integer("spp");
  s.run = r.integer("run");
  const nlohmann::json& list = r.array("strategies");
  for (size_t i = 0; i < list.size(); ++i) {
    const FieldReader st(list[i], r.file(), fmt::format("{}, \"strategies\"[{}]", r.where(), i));
    s.strategies.push_back({st.integer("s"), st.integer("t"), st.number("share"), list[i]});
  }
  // Present where the study had a reference image.
  if (r.object().contains("share_beyond_max_bounces"))
    s.shareBeyondMaxBounces = r.number("share_beyond_max_bounces");
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
      out.strategies.push_back(strategiesRun(r));
  }
}

}  // namespace verity::studies
