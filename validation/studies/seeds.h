// Seeds keyed by names, so that a run's seed does not depend on the order runs are made in.
#pragma once

#include <cstdint>
#include <string>

namespace verity::studies {

// The seed of run `run` of `integrator` at budget `budget` of a kind: a budget type's name
// (budget.h) or a study's own ("speedup", "bench").
uint64_t runSeed(const std::string& integrator, const std::string& kind, double budget, int run);
// The same with sampler `sampler` (a registry name): each sampler's runs have seeds of their
// own. The independent sampler's are runSeed's above, which it had before samplers were
// compared, so earlier records and bench figures repeat.
uint64_t runSeed(const std::string& integrator, const std::string& sampler, const std::string& kind,
                 double budget, int run);

}  // namespace verity::studies
