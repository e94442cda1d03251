#include "commands/reference_command.h"

#include <fmt/format.h>

#include "cli/max_bounces_option.h"
#include "cli/number_options.h"
#include "cli/output_paths.h"
#include "cli/seed_option.h"
#include "cli/subcommand.h"
#include "cli/threads_option.h"
#include "integrators/integrator_settings.h"
#include "validation/studies/reference.h"

namespace verity {

void addReferenceCommand(CLI::App& app, const ProcessGroup& group) {
  auto config = std::make_shared<studies::ReferenceConfig>();
  CLI::App* cmd = addSubcommand(
      app, "reference",
      "Render a reference image with variance channels: <folder>/<scene>.exr and <scene>.json",
      MpiUse::SplitsWork, group);
  cmd->add_option("scene", config->scene, "Scene file (.json)")->required();
  cmd->add_option("--spp", config->spp, "Samples per pixel")->check(wholeNumber(1));
  cmd->add_option("--integrator", config->integrator, "Integrator type")
      ->default_str("the scene's");
  addMaxBouncesOption(cmd, config->maxBounces);
  addThreadsOption(cmd, config->threads, MpiUse::SplitsWork);
  cmd->add_option("--resolution", config->resolution,
                  "Image width in pixels, the scene's aspect ratio kept")
      ->default_str("the scene's")
      ->check(wholeNumber(1));
  cmd->add_option("-o,--output", config->directory,
                  "Output folder of <scene>.exr and <scene>.json (created if missing)");
  addSeedOption(cmd, config->seed, "Seed, 0 to 2^64 - 1; 0: derived from the scene's name")
      ->default_str("0");
  cmd->callback([config, &group] {
    if (group.isRoot()) prepareOutputFolder(config->directory, "-o");
    const studies::ReferenceResult r = studies::makeReference(*config, group);
    if (!group.isRoot()) return;
    fmt::print(stderr, "{}: {} spp of {} at {}x{}, {:.2f} s; its own relative MSE {:.3g}\n",
               r.metadata["scene"].get<std::string>(), r.metadata["spp"].get<int>(),
               r.metadata["integrator"].get<std::string>(), r.metadata["width"].get<int>(),
               r.metadata["height"].get<int>(), r.metadata["wall_seconds"].get<double>(),
               r.metadata["rel_mse"].get<double>());
    fmt::print(stderr, "wrote {}\nwrote {}\n", r.image.string(), r.sidecar.string());
  });
}

}  // namespace verity
