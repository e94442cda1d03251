#include "validation/studies/reference_command.h"

#include <fmt/format.h>

#include "commands/seed_option.h"
#include "integrators/integrator_settings.h"
#include "validation/studies/reference.h"

namespace verity {

void addReferenceCommand(CLI::App& app, const ProcessGroup& group) {
  auto config = std::make_shared<studies::ReferenceConfig>();
  CLI::App* cmd = app.add_subcommand(
      "reference",
      "Render a reference image with variance channels: <dir>/<scene>.exr and <scene>.json");
  cmd->add_option("scene", config->scene, "Scene file (.json)")->required();
  cmd->add_option("--spp", config->spp, "Samples per pixel")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--integrator", config->integrator, "Integrator type (default: the scene's)");
  cmd->add_option("--max-bounces", config->maxBounces,
                  "Maximum scattering events per path (default: the scene's)")
      ->check(CLI::Range(0, kMaxBouncesLimit));
  cmd->add_option("--threads", config->threads,
                  "Worker threads per process (default: all cores; under mpirun, the host's "
                  "cores shared among its ranks)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--resolution", config->resolution,
                  "Image width in pixels (the scene's aspect ratio is kept)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--dir", config->directory, "Output folder")->capture_default_str();
  addSeedOption(cmd, config->seed,
                "Seed, 0 to 2^64 - 1 (default and 0: derived from the scene's name)");
  cmd->callback([config, &group] {
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
