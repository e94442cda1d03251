#include "cli/roulette_options.h"

#include "cli/number_options.h"
#include "integrators/integrator_registry.h"

namespace verity {

void addRouletteOptions(CLI::App* cmd, int& depth, float& threshold) {
  cmd->add_option("--rr-depth", depth,
                  "Scattering event after which Russian roulette first decides whether a path "
                  "goes on (the integrator's \"rr_depth\")")
      ->default_str("the scene's")
      ->check(wholeNumber(integrator_keys::kRrDepth.allowed));
  cmd->add_option("--rr-threshold", threshold,
                  "Throughput below which Russian roulette may end a path (the integrator's "
                  "\"rr_threshold\")")
      ->default_str("the scene's")
      ->check(realNumber(integrator_keys::kRrThreshold.allowed));
}

}  // namespace verity
