// The convergence study: error against a reference at growing budgets of samples or time,
// one seeded render per JSON line (resumable).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "distributed/process_group.h"
#include "validation/studies/budget.h"
#include "validation/studies/study_records.h"

namespace verity::studies {

struct ConvergenceConfig {
  std::filesystem::path scene;
  std::vector<std::string> integrators;
  // Sampler registry names, each run with every integrator; empty: the scene's own sampler.
  std::vector<std::string> samplers;
  int runs = 4;
  BudgetType budgetType = BudgetType::Spp;
  std::vector<double> budgets;
  std::vector<int> threads = {0};
  std::filesystem::path reference;  // "": references/<scene>.exr
  std::filesystem::path output = "results.jsonl";
  int resolution = 0;  // image width; 0: the reference's
  int maxBounces = -1;
  // Use a reference that records another scene (never one of another resolution).
  bool force = false;
  // Saves the relative error image (.npy next to the output) of run 0 of each integrator at
  // the largest budget and the first thread count, for the report's false-colour images.
  bool errorImages = true;
};

// Refuses a reference of another scene (unless `force`) or resolution before rendering.
// Runs, in this order: for each thread count, run index, budget, integrator and sampler
// (integrators and samplers alternate innermost so that a change in the machine's load hits
// them alike); each sampler's runs have seeds of their own (seeds.h). Runs whose key (scene,
// resolution, integrator, sampler, max bounces, threads, budget type, budget, run) is already
// in the output are skipped; a record there lacking one of those fields is an error naming
// the file, the record and the field. A record has rel_variance (the relative variance of the
// image from each pixel's own samples) only for a sampler whose samples are independent;
// others carry rel_variance_omitted, saying why. `log` gets one line per run. Over a distributed
// `group` the runs are dealt to its ranks (validation/studies/run_distribution.h).
StudyProgress runConvergenceStudy(const ConvergenceConfig& config,
                                  const std::function<void(const std::string&)>& log,
                                  const ProcessGroup& group = ProcessGroup::solo());

}  // namespace verity::studies
