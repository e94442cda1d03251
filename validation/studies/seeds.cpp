#include "validation/studies/seeds.h"

#include <fmt/format.h>

#include "core/hash.h"

namespace verity::studies {

uint64_t hashString(const std::string& s) {
  uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a offset basis and prime (Fowler, Noll, Vo)
  for (unsigned char c : s) {
    h ^= c;
    h *= 0x100000001b3ull;
  }
  return h;
}

uint64_t runSeed(const std::string& integrator, const std::string& budgetType, double budget,
                 int run) {
  // The budget by its shortest decimal form, so that 0.1 s and 0.10 s give the same seed.
  return hashValues(hashString(integrator), hashString(budgetType),
                    hashString(fmt::format("{}", budget)), uint64_t(run));
}

uint64_t runSeed(const std::string& integrator, const std::string& sampler,
                 const std::string& budgetType, double budget, int run) {
  const uint64_t seed = runSeed(integrator, budgetType, budget, run);
  return sampler == "independent" ? seed : hashValues(seed, hashString(sampler));
}

}  // namespace verity::studies
