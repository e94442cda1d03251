// `verity chi2`: runs one sampling-test configuration and reports every check, or prints
// the seed report's sample-test table next to this suite's figures.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

void addChi2Command(CLI::App& app);

}  // namespace verity
