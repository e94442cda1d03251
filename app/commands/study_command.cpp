#include "commands/study_command.h"

#include <fmt/format.h>

#include "cli/max_bounces_option.h"
#include "cli/number_options.h"
#include "cli/output_paths.h"
#include "cli/subcommand.h"
#include "cli/threads_option.h"
#include "integrators/integrator_registry.h"
#include "integrators/integrator_settings.h"
#include "sampling/sampler_registry.h"
#include "validation/studies/convergence.h"
#include "validation/studies/json_lines.h"
#include "validation/studies/speedup.h"
#include "validation/studies/strategies.h"
#include "validation/studies/summary.h"

namespace verity {

namespace {

void printSummary(const std::filesystem::path& results) {
  const auto records = studies::readJsonLines(results);
  fmt::print("{}", studies::summaryText(studies::summarize(records, results.string())));
}

void logLine(const std::string& line) {
  fmt::print(stderr, "{}\n", line);
}

// --spp or --time: the budgets of a study, one list or the other.
struct Budgets {
  std::shared_ptr<std::vector<int>> spp = std::make_shared<std::vector<int>>();
  std::shared_ptr<std::vector<double>> time = std::make_shared<std::vector<double>>();
  studies::BudgetType type() const {
    return time->empty() ? studies::BudgetType::Spp : studies::BudgetType::Time;
  }
  std::vector<double> values() const {
    return time->empty() ? std::vector<double>(spp->begin(), spp->end()) : *time;
  }
};

Budgets addBudgetOptions(CLI::App* cmd, const std::string& sppHelp) {
  Budgets b;
  CLI::Option* sppOption =
      cmd->add_option("--spp", *b.spp, sppHelp)->delimiter(',')->check(wholeNumber(1));
  CLI::Option* timeOption =
      cmd->add_option("--time", *b.time, "Budgets in seconds of wall time, comma-separated")
          ->delimiter(',')
          ->check(realNumber(0, false));
  sppOption->excludes(timeOption);
  timeOption->excludes(sppOption);
  return b;
}

void addConvergence(CLI::App& study, const ProcessGroup& group) {
  auto config = std::make_shared<studies::ConvergenceConfig>();
  auto output = std::make_shared<std::string>("results.jsonl");
  auto reference = std::make_shared<std::string>();
  auto noImages = std::make_shared<bool>(false);
  CLI::App* cmd = addSubcommand(
      study, "convergence",
      "Independent seeded runs per integrator, sampler and budget: relative MSE against a "
      "reference, wall and CPU time; appended to a JSON Lines file and resumable",
      MpiUse::SplitsWork, group);
  cmd->add_option("scene", config->scene, "Scene file (.json)")->required();
  cmd->add_option("--integrator", config->integrators, "Integrators, comma-separated")
      ->required()
      ->delimiter(',');
  cmd->add_option("--sampler", config->samplers,
                  "Samplers, comma-separated, each run with every integrator and seeds of its "
                  "own (a sampler other than the scene's takes its keys' defaults); one of " +
                      samplerTypeList() +
                      ". Only independent samples give the rel_variance column; other "
                      "samplers' records leave it out")
      ->default_str("the scene's")
      ->delimiter(',');
  cmd->add_option("--runs", config->runs, "Independent runs per integrator, sampler and budget")
      ->check(wholeNumber(1));
  const Budgets budgets = addBudgetOptions(cmd, "Budgets in samples per pixel, comma-separated");
  addThreadCountsOption(cmd, config->threads, 0);
  cmd->add_option("--reference", *reference, "Reference EXR with variance channels")
      ->default_str("references/<scene>.exr");
  cmd->add_option("-o,--output", *output,
                  "Results file (JSON Lines; appended to; missing folders are created)");
  cmd->add_option("--resolution", config->resolution,
                  "Image width in pixels, the scene's aspect ratio kept")
      ->default_str("the reference's")
      ->check(wholeNumber(1));
  addMaxBouncesOption(cmd, config->maxBounces);
  cmd->add_flag("--no-error-images", *noImages,
                "Do not save relative-error images at the largest budget");
  cmd->add_flag("--force", config->force,
                "Use a reference that records another scene (a warning instead of an error)");
  cmd->callback([=, &group] {
    if (budgets.values().empty()) throw CLI::RequiredError("--spp or --time (the budgets)");
    config->budgetType = budgets.type();
    config->budgets = budgets.values();
    config->output = *output;
    if (group.isRoot()) prepareOutputFile(*output, "-o");
    config->reference = *reference;
    config->errorImages = !*noImages;
    const studies::StudyProgress p = studies::runConvergenceStudy(*config, logLine, group);
    if (!group.isRoot()) return;
    fmt::print(stderr, "{} runs done, {} already in {}\n", p.done, p.skipped, *output);
    printSummary(*output);
  });
}

void addSpeedup(CLI::App& study, const ProcessGroup& group) {
  auto config = std::make_shared<studies::SpeedupConfig>();
  auto output = std::make_shared<std::string>("speedup.jsonl");
  CLI::App* cmd = addSubcommand(
      study, "speedup",
      "Time per integrator and thread count (alternating, medians): speed-up and parallel "
      "efficiency",
      MpiUse::SplitsWork, group);
  cmd->add_option("scene", config->scene, "Scene file (.json)")->required();
  addThreadCountsOption(cmd, config->threads, 1);
  cmd->add_option("--integrator", config->integrators, "Integrators, comma-separated")
      ->required()
      ->delimiter(',');
  cmd->add_option("--spp", config->spp, "Samples per pixel of each timed render")
      ->check(wholeNumber(1));
  cmd->add_option("--repeats", config->repeats, "Alternating repeats")->check(wholeNumber(1));
  cmd->add_option("--resolution", config->resolution,
                  "Image width in pixels, the scene's aspect ratio kept")
      ->default_str("the scene's")
      ->check(wholeNumber(1));
  addMaxBouncesOption(cmd, config->maxBounces);
  cmd->add_option("-o,--output", *output,
                  "Results file (JSON Lines; appended to; missing folders are created)");
  cmd->callback([=, &group] {
    config->output = *output;
    if (group.isRoot()) prepareOutputFile(*output, "-o");
    const studies::StudyProgress p = studies::runSpeedupStudy(*config, logLine, group);
    if (!group.isRoot()) return;
    fmt::print(stderr, "{} renders done, {} already in {}\n", p.done, p.skipped, *output);
    printSummary(*output);
  });
}

void addStrategies(CLI::App& study, const ProcessGroup& group) {
  auto config = std::make_shared<studies::StrategiesConfig>();
  auto reference = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>("strategies.jsonl");
  auto noImages = std::make_shared<bool>(false);
  CLI::App* cmd = addSubcommand(
      study, "strategies",
      "BDPT split into its strategies (s, t) per run and budget: each strategy's share of the "
      "image and the relative variance of its weighted and unweighted images, beside BDPT's "
      "and a path tracer's path-length images",
      MpiUse::OneProcess, group);
  cmd->add_option("scene", config->scene, "Scene file (.json)")->required();
  const Budgets budgets = addBudgetOptions(cmd, "Budgets in samples per pixel, comma-separated");
  cmd->get_option("--spp")->default_str("64");
  cmd->add_option("--runs", config->runs, "Independent runs per budget")->check(wholeNumber(1));
  cmd->add_option("--max-bounces", config->maxBounces,
                  "Maximum scattering events per path (0: emitters seen directly)")
      ->check(wholeNumber(integrator_keys::kMaxBounces.allowed));
  cmd->add_option("--path-tracer", config->pathTracer,
                  "The path tracer whose path-length images are set beside the strategies");
  cmd->add_option("--resolution", config->resolution,
                  "Image width in pixels, the scene's aspect ratio kept")
      ->default_str("the reference's, else the scene's")
      ->check(wholeNumber(1));
  addThreadsOption(cmd, config->threads, MpiUse::OneProcess);
  cmd->add_option("--reference", *reference,
                  "Reference EXR of the full image, for the share of longer paths (optional)");
  cmd->add_option("-o,--output", *output,
                  "Results file (JSON Lines; appended to; missing folders are created)");
  cmd->add_flag("--no-images", *noImages,
                "Do not save the weighted strategy images at the largest budget");
  cmd->add_flag("--force", config->force,
                "Use a reference that records another scene (a warning instead of an error)");
  cmd->callback([=] {
    config->budgetType = budgets.type();
    if (!budgets.values().empty()) config->budgets = budgets.values();
    config->reference = *reference;
    config->output = *output;
    prepareOutputFile(*output, "-o");
    config->images = !*noImages;
    const studies::StudyProgress p = studies::runStrategiesStudy(*config, logLine);
    fmt::print(stderr, "{} records done, {} already in {}\n", p.done, p.skipped, *output);
    printSummary(*output);
  });
}

}  // namespace

void addStudyCommand(CLI::App& app, const ProcessGroup& group) {
  CLI::App* study = addSubcommand(app, "study", "Convergence, speed-up and BDPT strategy studies",
                                  MpiUse::SplitsWork, group);
  study->require_subcommand(1);
  addConvergence(*study, group);
  addSpeedup(*study, group);
  addStrategies(*study, group);
}

}  // namespace verity
