// `--rr-depth N` and `--rr-threshold T`, as the commands that render one scene spell them: the
// integrator's "rr_depth" and "rr_threshold" unless given.
#pragma once

#include <CLI/CLI.hpp>

namespace verity {

// 0 left in either: the scene's value.
void addRouletteOptions(CLI::App* cmd, int& depth, float& threshold);

}  // namespace verity
