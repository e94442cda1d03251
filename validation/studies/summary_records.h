// The study records the summary reads, as typed values. Each field the summary uses is
// required: a record that lacks one, or holds a value of the wrong type, is an error naming
// the file, the record and the key, never a default that would enter the tables as 0.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "validation/studies/budget.h"

namespace verity::studies {

// One render of a convergence study.
struct ConvergenceRun {
  std::string scene, integrator, sampler;
  BudgetType budgetType = BudgetType::Spp;
  int width = 0, height = 0, maxBounces = 0, threads = 0, spp = 0;
  double budget = 0, wallSeconds = 0, cpuSeconds = 0, relMse = 0;
  double relMseEpsilon = 0, referenceRelMse = 0;
  // Required where the sampler's samples are independent; none otherwise (convergence.h).
  std::optional<double> relVariance;
};

// One timed render of a speed-up study.
struct SpeedupRun {
  std::string scene, integrator;
  int width = 0, height = 0, maxBounces = 0, spp = 0, threads = 0;
  double wallSeconds = 0, cpuSeconds = 0;
};

// One BDPT strategy (s, t) of a strategies record: its share of the image, and the record's
// object as written (the summary lists it whole).
struct StrategyShare {
  int s = 0, t = 0;
  double share = 0;
  nlohmann::json fields;
};

// One BDPT render of a strategies study.
struct StrategiesRun {
  std::string scene;
  int width = 0, height = 0, maxBounces = 0, spp = 0, run = 0;
  std::vector<StrategyShare> strategies;
  std::optional<double> shareBeyondMaxBounces;
};

struct SummaryRecords {
  std::vector<ConvergenceRun> convergence;
  std::vector<SpeedupRun> speedup;
  std::vector<StrategiesRun> strategies;
};

// Appends the convergence, speed-up and strategies records among `records`, read from `file`
// (other studies' records are left out). Throws VerityError naming `file`, the record (its
// position among the file's records) and the key that is missing or of the wrong type.
void addSummaryRecords(const std::vector<nlohmann::json>& records, const std::string& file,
                       SummaryRecords& out);

}  // namespace verity::studies
