// The --threads option of the commands that run on oneTBB: a whole number of worker threads, 0
// (the default) meaning all cores; anything else (negative, fractional) is refused by name
// (number_options.h). The studies that compare thread counts take a comma-separated list of
// them instead, with the same check and the same meaning of 0.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "cli/subcommand.h"

namespace verity {

// Adds "--threads" to `cmd`, stored in `threads`. A command that splits its work over MPI
// ranks (MpiUse::SplitsWork) counts them per process; `whose` ("of the --reference renders")
// says which of the command's work they run where that is not all of it.
CLI::Option* addThreadsOption(CLI::App* cmd, int& threads, MpiUse use,
                              const std::string& whose = "");

// Adds "--threads" as thread counts, comma-separated, each at least `min` (0 or 1).
CLI::Option* addThreadCountsOption(CLI::App* cmd, std::vector<int>& counts, int min);

}  // namespace verity
