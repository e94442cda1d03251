#include "validation/studies/convergence.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.h"
#include "film/image_io.h"
#include "validation/studies/npy_file.h"
#include "validation/studies/reference_match.h"
#include "validation/studies/relative_error.h"
#include "validation/studies/run_distribution.h"
#include "validation/studies/seeds.h"
#include "validation/studies/study_sampler.h"
#include "validation/studies/study_scene.h"
#include "validation/studies/timed_render.h"

namespace verity::studies {

namespace {

// What tells one run of the study from another.
struct ConvergenceRunKey {
  std::string scene;
  int width, height;
  std::string integrator, sampler;
  int maxBounces, threads;
  BudgetType budgetType;
  double budget;
  int run;
  auto operator<=>(const ConvergenceRunKey&) const = default;
};

ConvergenceRunKey convergenceRunKey(const FieldReader& r) {
  return {r.text("scene"),    r.integer("width"),       r.integer("height"),  r.text("integrator"),
          r.text("sampler"),  r.integer("max_bounces"), r.integer("threads"), readBudgetType(r),
          r.number("budget"), r.integer("run")};
}

}  // namespace

StudyProgress runConvergenceStudy(const ConvergenceConfig& config,
                                  const std::function<void(const std::string&)>& log,
                                  const ProcessGroup& group) {
  checkBudgets(config.budgetType, config.budgets);

  const std::string sceneName = config.scene.stem().string();
  const std::filesystem::path referencePath =
      config.reference.empty() ? std::filesystem::path("references") / (sceneName + ".exr")
                               : config.reference;
  if (!std::filesystem::exists(referencePath))
    throw VerityError(referencePath.string(), "",
                      "no reference image: make one with `verity reference` or pass --reference");
  const ImageChannels reference = readReference(referencePath);
  const double referenceOwnRelMse = referenceRelMse(reference);
  auto attribute = [&](const std::string& name) {
    const auto it = reference.attributes.find(name);
    return it == reference.attributes.end() ? std::string() : it->second;
  };

  // The study renders at the reference's resolution unless told otherwise (and then the
  // comparison reports the mismatch).
  const SceneFile file = loadScene(
      config.scene,
      SceneOverrides::atWidth(config.resolution > 0 ? config.resolution : reference.width));
  const std::vector<StudySampler> samplers = prepareSamplers(file, config.samplers, "--sampler");
  std::vector<PreparedIntegrator> integrators =
      prepareIntegrators(file, config.integrators, config.maxBounces);
  const Vector2i resolution = file.scene->camera().resolution();
  checkReferenceMatches(referencePath, reference, config.scene, resolution, config.resolution > 0,
                        config.force, log);

  const MachineInfo machine = machineInfo();
  KeyedStudyOutput output(config.output, "convergence", convergenceRunKey);
  const double largestBudget = *std::max_element(config.budgets.begin(), config.budgets.end());
  const std::filesystem::path imageDir =
      config.output.parent_path() / (config.output.stem().string() + "-images");

  // Thread count 0 ("all cores") is recorded as the count it means.
  std::vector<int> threadCounts = config.threads;
  for (int& t : threadCounts)
    if (t <= 0) t = std::max(1, machine.cores);

  std::vector<StudyRun> runs;
  for (size_t ti = 0; ti < config.threads.size(); ++ti)
    for (int run = 0; run < config.runs; ++run)
      for (double budget : config.budgets)
        for (const PreparedIntegrator& p : integrators)
          for (const StudySampler& s : samplers) {
            nlohmann::json header =
                recordHeader("convergence", config.scene, resolution, p.settings);
            header.update({
                {"sampler", s.type},
                {"threads", threadCounts[ti]},
                {"budget_type", budgetTypeName(config.budgetType)},
                {"budget", budget},
                {"run", run},
            });
            runs.push_back(
                {header, [&, ti, run, budget, &p = p, &s = s](nlohmann::json& record) {
                   const uint64_t seed = runSeed(p.settings.type->name, s.type,
                                                 budgetTypeName(config.budgetType), budget, run);
                   Film film(resolution);
                   const bool byTime = config.budgetType == BudgetType::Time;
                   const TimedRender timed =
                       timedRender(file, *s.prototype, *p.integrator, film,
                                   byTime ? 0 : int(std::lround(budget)), threadCounts[ti], seed,
                                   byTime ? budget : 0);
                   const ErrorStats error = compareToReference(film, reference);
                   record.update({
                       {"seed", seed},
                       {"spp", timed.stats.passes},
                       {"wall_seconds", timed.wallSeconds},
                       {"cpu_seconds", timed.cpuSeconds},
                       {"rays", timed.stats.rays},
                       {"invalid_samples", timed.stats.invalidSamples},
                       {"rel_mse", error.relMse},
                       {"rel_mse_epsilon", kRelEpsilon},
                       {"efficiency", 1.0 / (error.relMse * timed.wallSeconds)},
                       {"reference", referencePath.string()},
                       {"reference_spp", attribute("verity:spp")},
                       {"reference_integrator", attribute("verity:integrator")},
                       {"reference_rel_mse", referenceOwnRelMse},
                   });
                   if (s.prototype->samplesAreIndependent())
                     record.update({{"rel_variance", error.relVariance},
                                    {"mean_variance", error.meanVariance}});
                   else
                     record["rel_variance_omitted"] = kCorrelatedSamplesNote;
                   record.update(provenance(machine));
                   if (config.errorImages && ti == 0 && run == 0 && budget == largestBudget) {
                     std::filesystem::create_directories(imageDir);
                     const std::filesystem::path npy =
                         imageDir / fmt::format("{}_{}_{}_{}{}.npy", sceneName,
                                                p.settings.type->name, s.type, budget,
                                                budgetUnit(config.budgetType));
                     writeHalfNpy(npy, relativeErrorImage(film, reference),
                                  {size_t(film.height()), size_t(film.width())});
                     record["error_image"] =
                         std::filesystem::relative(npy, config.output.parent_path().empty()
                                                            ? std::filesystem::path(".")
                                                            : config.output.parent_path())
                             .string();
                   }
                   return fmt::format(
                       "{} {} threads={} {}={} run={}: {} spp, {:.3f} s wall, {:.3f} s "
                       "CPU, relMSE {:.4g}",
                       p.settings.type->name, s.type, threadCounts[ti],
                       budgetTypeName(config.budgetType), budget, run, timed.stats.passes,
                       timed.wallSeconds, timed.cpuSeconds, error.relMse);
                 }});
          }
  return executeRuns(group, *std::max_element(threadCounts.begin(), threadCounts.end()), output,
                     runs, log);
}

}  // namespace verity::studies
