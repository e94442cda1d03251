// `verity study convergence` and `verity study speedup`: many seeded renders, timed and
// compared against a reference, recorded as JSON Lines and summarised.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

void addStudyCommand(CLI::App& app);

}  // namespace verity
