#include "validation/studies/seeds.h"

#include <fmt/format.h>

#include "core/hash.h"

namespace verity::studies {

uint64_t runSeed(const std::string& integrator, const std::string& kind, double budget, int run) {
  // The budget by its shortest decimal form, so that 0.1 s and 0.10 s give the same seed.
  return hashValues(hashString(integrator), hashString(kind), hashString(fmt::format("{}", budget)),
                    uint64_t(run));
}

uint64_t runSeed(const std::string& integrator, const std::string& sampler, const std::string& kind,
                 double budget, int run) {
  const uint64_t seed = runSeed(integrator, kind, budget, run);
  return sampler == "independent" ? seed : hashValues(seed, hashString(sampler));
}

}  // namespace verity::studies
