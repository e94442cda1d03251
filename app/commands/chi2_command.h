// `verity chi2`: runs one sampling-test configuration and reports every check, or prints
// the seed report's sample-test table next to this suite's figures.
#pragma once

#include <CLI/CLI.hpp>

#include "distributed/process_group.h"

namespace verity {

// Runs in one process.
void addChi2Command(CLI::App& app, const ProcessGroup& group);

}  // namespace verity
