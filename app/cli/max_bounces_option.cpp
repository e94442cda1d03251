#include "cli/max_bounces_option.h"

#include "cli/number_options.h"
#include "integrators/integrator_registry.h"

namespace verity {

CLI::Option* addMaxBouncesOption(CLI::App* cmd, int& maxBounces) {
  return cmd
      ->add_option("--max-bounces", maxBounces,
                   "Maximum scattering events per path (0: emitters seen directly)")
      ->default_str("the scene's")
      ->check(wholeNumber(integrator_keys::kMaxBounces.allowed));
}

}  // namespace verity
